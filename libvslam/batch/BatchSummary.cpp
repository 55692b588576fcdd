#include <libvslam/batch/BatchSummary.h>
#include <libvslam/batch/BatchTask.h>
#include <libvslam/core/InputError.h>
#include <libvslam/eval/Charts.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

namespace vslam::batch
{
namespace
{
struct Spread
{
	double mean = NAN, std = NAN;
	size_t n = 0;
};

Spread spreadOf(const std::vector<Metrics>& runs, const std::string& key)
{
	std::vector<double> v;
	for (const auto& m : runs)
		if (const auto it = m.find(key); it != m.end() && std::isfinite(it->second)) v.push_back(it->second);
	Spread s;
	s.n = v.size();
	if (v.empty()) return s;
	double sum = 0;
	for (const double x : v) sum += x;
	s.mean = sum / double(v.size());
	double sq = 0;
	for (const double x : v) sq += (x - s.mean) * (x - s.mean);
	s.std = v.size() > 1 ? std::sqrt(sq / double(v.size() - 1)) : 0.0;  // sample standard deviation
	return s;
}

std::string cell(const Spread& s, const char* format)
{
	if (s.n == 0) return "-";
	char a[32], b[32];
	std::snprintf(a, sizeof a, format, s.mean);
	std::snprintf(b, sizeof b, format, s.std);
	return std::string(a) + " +- " + b;
}

double total(const std::vector<Metrics>& runs, const std::string& key)
{
	double sum = 0;
	for (const auto& m : runs)
		if (const auto it = m.find(key); it != m.end() && std::isfinite(it->second)) sum += it->second;
	return sum;
}
/** The table the homes are judged by: vslam beside dead reckoning and
 * rbpf-slam with the laser, and how often vslam is worse than dead reckoning. */
std::string againstPeers(const BatchPlan& plan, const std::map<std::string, Metrics>& byRun)
{
	std::ostringstream md;
	md << "\n| scenario | variation | runs | vslam ATE mean [m] | vslam ATE median [m] | dead reckoning ATE mean [m] | "
		  "rbpf-slam (laser) ATE mean, aligned [m] | vslam / dead reckoning (mean ATE) | runs worse than dead reckoning |\n"
	   << "|---|---|---|---|---|---|---|---|---|\n";
	for (size_t si = 0; si < plan.scenarios.size(); si++)
		for (size_t vi = 0; vi < plan.variations.size(); vi++)
		{
			const Scenario& s = plan.scenarios[si];
			std::vector<Metrics> runs, peers;
			int worse = 0;
			double vslamSum = 0, odoSum = 0;
			for (const auto& t : plan.tasks)
			{
				if (t.kind != Task::Kind::Run || t.scenario != si || t.variation != vi) continue;
				const Metrics& m = byRun.at(t.id);
				if (m.empty() || !m.count("ate_mean") || !m.count("odometry_ate_mean")) continue;
				runs.push_back(m);
				worse += m.at("ate_mean") > m.at("odometry_ate_mean");
				vslamSum += m.at("ate_mean"), odoSum += m.at("odometry_ate_mean");
				if (!plan.rbpfSlamIni.empty()) peers.push_back(readMetrics(plan.peerDirOf(s, t.seed) + "/metrics.txt"));
			}
			char ratio[32] = "-", share[48] = "-";
			if (!runs.empty())
			{
				std::snprintf(ratio, sizeof ratio, "%.2f", odoSum > 0 ? vslamSum / odoSum : NAN);
				std::snprintf(share, sizeof share, "%d / %zu", worse, runs.size());
			}
			md << "| " << s.name << " | " << plan.variations[vi].label() << " | " << runs.size() << " | "
			   << cell(spreadOf(runs, "ate_mean"), "%.3f") << " | " << cell(spreadOf(runs, "ate_median"), "%.3f") << " | "
			   << cell(spreadOf(runs, "odometry_ate_mean"), "%.3f") << " | " << cell(spreadOf(peers, "ate_aligned_mean"), "%.3f")
			   << " | " << ratio << " | " << share << " |\n";
		}
	return md.str();
}
}  // namespace

std::string writeBatchSummary(const BatchPlan& plan)
{
	std::ostringstream md;
	md << "| scenario | variation | runs | ATE RMSE [m] | ATE RMSE aligned [m] | ATE median [m] | ATE mean [m] | "
		  "most-likely path ATE RMSE / aligned [m] | RPE 1 s [m] | odometry ATE RMSE [m] | odometry ATE median [m] | odometry RPE 1 s [m] | kidnaps recovered within 10 s (to 0.3 m; to "
		  "the error level before) | "
		  "wall time [s] | x real time | peak memory [MiB] |\n"
	   << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
	std::ofstream csv(plan.outputDir + "/summary.csv");
	if (!csv) throw InputError("cannot write '" + plan.outputDir + "/summary.csv'");
	std::set<std::string> keys;
	std::map<std::string, Metrics> byRun;
	for (const auto& t : plan.tasks)
		if (t.kind == Task::Kind::Run)
			for (const auto& [k, v] : byRun[t.id] = readMetrics(t.dir + "/metrics.txt")) keys.insert(k);
	csv << "scenario,variation,settings,seed";
	for (const auto& k : keys) csv << "," << k;
	csv << "\n";

	std::vector<double> bars, spreads;
	std::vector<std::string> labels;
	std::vector<std::array<uint8_t, 3>> colours;
	for (size_t si = 0; si < plan.scenarios.size(); si++)
		for (size_t vi = 0; vi < plan.variations.size(); vi++)
		{
			const Scenario& s = plan.scenarios[si];
			const Variation& v = plan.variations[vi];
			std::vector<Metrics> runs;
			size_t planned = 0;
			for (const auto& t : plan.tasks)
			{
				if (t.kind != Task::Kind::Run || t.scenario != si || t.variation != vi) continue;
				planned++;
				const Metrics& m = byRun[t.id];
				if (m.empty()) continue;
				runs.push_back(m);
				csv << s.name << "," << v.name << ",\"" << v.label() << "\"," << t.seed;
				for (const auto& k : keys)
				{
					const auto it = m.find(k);
					csv << ",";
					if (it != m.end()) csv << it->second;
				}
				csv << "\n";
			}
			const double kidnaps = total(runs, "kidnaps");
			char kidnapCell[64] = "-";
			if (kidnaps > 0)
				std::snprintf(kidnapCell, sizeof kidnapCell, "%.0f / %.0f (%.0f to prior level)",
					total(runs, "kidnaps_recovered_10s"), kidnaps, total(runs, "kidnaps_recovered_10s_to_prior_level"));
			md << "| " << s.name << " | " << v.label() << " | " << runs.size() << " / " << planned
			   << " | " << cell(spreadOf(runs, "ate_rmse"), "%.3f") << " | "
			   << cell(spreadOf(runs, "ate_aligned_rmse"), "%.3f") << " | " << cell(spreadOf(runs, "ate_median"), "%.3f")
			   << " | " << cell(spreadOf(runs, "ate_mean"), "%.3f") << " | "
			   << cell(spreadOf(runs, "smoothed_ate_rmse"), "%.3f") << " / "
			   << cell(spreadOf(runs, "smoothed_ate_aligned_rmse"), "%.3f") << " | " << cell(spreadOf(runs, "rpe_1s_rmse"), "%.3f")
			   << " | " << cell(spreadOf(runs, "odometry_ate_rmse"), "%.3f") << " | "
			   << cell(spreadOf(runs, "odometry_ate_median"), "%.3f") << " | "
			   << cell(spreadOf(runs, "odometry_rpe_1s_rmse"), "%.3f") << " | " << kidnapCell << " | "
			   << cell(spreadOf(runs, "wall_s"), "%.1f") << " | " << cell(spreadOf(runs, "real_time_factor"), "%.1f")
			   << " | " << cell(spreadOf(runs, "peak_mib"), "%.0f") << " |\n";
			const Spread ate = spreadOf(runs, "ate_rmse"), odo = spreadOf(runs, "odometry_ate_rmse");
			bars.insert(bars.end(), {ate.mean, odo.mean});
			spreads.insert(spreads.end(), {ate.std, odo.std});
			labels.push_back(s.name + " " + std::to_string(vi + 1));
			labels.push_back("  (odometry)");
			colours.push_back({0, 60, 220});
			colours.push_back({220, 0, 0});
		}
	md << againstPeers(plan, byRun);
	std::ofstream(plan.outputDir + "/summary.md") << md.str();
	TChartOptions o;
	o.title = "ATE RMSE over seeds (mean +- std): vslam (blue), odometry alone (red); "
			  "'scenario k': its k-th variation in summary.md";
	o.xLabel = "";
	o.yLabel = "ATE RMSE [m]";
	o.width = std::max(480, 70 * int(bars.size()) + 160);
	writeBarChart(bars, {0, 60, 220}, o, plan.outputDir + "/summary_ate.png", spreads, labels, colours);
	return md.str();
}
}  // namespace vslam::batch

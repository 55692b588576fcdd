#include <libvslam/app/RunSummary.h>
#include <libvslam/batch/BatchTask.h>
#include <libvslam/batch/ProcessRun.h>
#include <libvslam/core/InputError.h>
#include <libvslam/eval/AbsoluteTrajectoryError.h>
#include <libvslam/eval/KidnapRecovery.h>
#include <libvslam/eval/Median.h>
#include <libvslam/eval/RelativePoseError.h>
#include <libvslam/eval/RunFigures.h>
#include <libvslam/world/FloorPlanFile.h>

#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>

namespace fs = std::filesystem;

namespace vslam::batch
{
namespace
{
std::string joined(const std::vector<std::string>& args)
{
	std::string s;
	for (const auto& a : args) s += (s.empty() ? "" : " ") + a;
	return s;
}

std::string readText(const std::string& file)
{
	std::ifstream in(file);
	return {std::istreambuf_iterator<char>(in), {}};
}

/** Bumped whenever the metrics change: finished runs are then scored again
 * from their outputs (no rerun). */
constexpr double kScoringVersion = 7;

/** Median error over the minute before \a t (the run's error level). */
double errorBefore(const AteStats& ate, double t)
{
	std::vector<double> before;
	for (size_t i = 0; i < ate.times.size(); i++)
		if (ate.times[i] >= t - 60 && ate.times[i] < t) before.push_back(ate.errors[i]);
	return before.empty() ? NAN : median(before);
}

/** Kidnaps: the ground truth jumps while the run lasts. Recovered within
 * 10 s: the error comes within 0.3 m and stays for 5 s; and, since a SLAM
 * map is itself off by the run's error level, also to that level: within
 * twice the median error of the minute before the kidnap (at least 0.3 m). */
void scoreKidnaps(const AteStats& ate, const Trajectory& truth, Metrics& m)
{
	double kidnaps = 0, recovered = 0, worst = 0, recoveredToLevel = 0, worstToLevel = 0;
	for (const size_t i : truthJumps(truth))
	{
		if (truth[i].t > ate.times.back()) continue;
		kidnaps++;
		const auto t = recoveryTime(ate.times, ate.errors, truth[i].t);
		if (t && *t <= 10) recovered++;
		worst = std::max(worst, t ? *t : INFINITY);
		RecoveryCriterion level;
		level.within = std::max(0.3, 2 * errorBefore(ate, truth[i].t));
		const auto tl = recoveryTime(ate.times, ate.errors, truth[i].t, level);
		if (tl && *tl <= 10) recoveredToLevel++;
		worstToLevel = std::max(worstToLevel, tl ? *tl : INFINITY);
	}
	m["kidnaps"] = kidnaps;
	m["kidnaps_recovered_10s"] = recovered;
	m["kidnaps_recovered_10s_to_prior_level"] = recoveredToLevel;
	if (kidnaps > 0) m["recovery_s_worst"] = worst, m["recovery_s_worst_to_prior_level"] = worstToLevel;
}

Metrics scoreRun(const BatchPlan& plan, const Task& task, double wallSeconds, double peakMiB)
{
	const Scenario& s = plan.scenarios[task.scenario];
	const std::string out = task.dir + "/vslam";
	const Trajectory estimate = readTrajectory(out + "/estimated_path.tum");
	const Trajectory odometry = readTrajectory(out + "/odometry_path.tum");
	const Trajectory truth = readTrajectory(plan.groundTruthOf(s, task.seed));
	Metrics m;
	TAteOptions raw, aligned;
	aligned.align = true;
	const AteStats ate = computeAte(estimate, truth, raw), ateAligned = computeAte(estimate, truth, aligned);
	if (ate.associated == 0) throw InputError("no pose of the estimate has ground truth at its time");
	m["ate_rmse"] = ate.rmse;
	m["ate_mean"] = ate.mean;
	m["ate_median"] = ate.median;
	m["ate_max"] = ate.max;
	m["ate_aligned_rmse"] = ateAligned.rmse;
	m["heading_rmse_deg"] = ate.headingRmse * 180 / M_PI;
	// The best particle's path at the end, smoothed by resampling.
	const Trajectory smoothed = readTrajectory(out + "/most_likely_path.tum");
	const AteStats smoothedAte = computeAte(smoothed, truth, raw);
	m["smoothed_ate_rmse"] = smoothedAte.rmse;
	m["smoothed_ate_median"] = smoothedAte.median;
	m["smoothed_ate_aligned_rmse"] = computeAte(smoothed, truth, aligned).rmse;
	const RpeStats rpe = computeRpe(estimate, truth);
	m["rpe_1s_rmse"] = rpe.translation.rmse;
	m["rpe_1s_max"] = rpe.translation.max;
	// The continuous pose for a controller (runs of vslam since it writes one).
	if (fs::exists(out + "/smoothed_path.tum"))
	{
		const Trajectory continuous = readTrajectory(out + "/smoothed_path.tum");
		const RpeStats r = computeRpe(continuous, truth);
		m["smoothed_path_rpe_1s_rmse"] = r.translation.rmse;
		m["smoothed_path_rpe_1s_max"] = r.translation.max;
		m["smoothed_path_ate_mean"] = computeAte(continuous, truth, raw).mean;
	}
	m["rpe_1s_rot_rmse_deg"] = rpe.rotation.rmse * 180 / M_PI;
	const AteStats odo = computeAte(odometry, truth, raw);
	m["odometry_ate_rmse"] = odo.rmse;
	m["odometry_ate_median"] = odo.median;
	m["odometry_ate_mean"] = odo.mean;
	m["odometry_rpe_1s_rmse"] = computeRpe(odometry, truth).translation.rmse;
	scoreKidnaps(ate, truth, m);
	const auto summary = readRunSummary(out + "/run_summary.yaml");
	m["kidnaps_declared"] = summaryNumber(summary, "filter.kidnaps_detected");
	m["kidnaps_reverted"] = summaryNumber(summary, "filter.kidnaps_reverted");
	m["landmarks"] = summaryNumber(summary, "landmarks.total");
	m["data_s"] = summaryNumber(summary, "rawlog.data_seconds");
	m["wall_s"] = wallSeconds;
	m["peak_mib"] = peakMiB;
	m["real_time_factor"] = wallSeconds > 0 ? m["data_s"] / wallSeconds : NAN;
	m["scoring_version"] = kScoringVersion;

	// The paper's figures of the run, as `vslam-eval --run` writes them.
	std::optional<world::FloorPlan> floorPlan;
	if (const std::string w = plan.worldOf(s, task.seed); !w.empty()) floorPlan = world::loadFloorPlan(w, "/usr/share");
	RunFigureSources figures;
	figures.estimate = &estimate;
	figures.truth = &truth;
	figures.odometry = &odometry;
	figures.plan = floorPlan ? &*floorPlan : nullptr;
	figures.runDir = out;
	writeRunFigures(figures, out + "/figures");
	return m;
}

void writeMetrics(const std::string& file, const Metrics& m)
{
	std::ofstream out(file);
	for (const auto& [k, v] : m) out << k << " " << v << "\n";
}

/** What a task ran, as its done file records it: the command with the
 * program's folder left out, so that finished tasks stay finished when the
 * binaries move (another build folder, an installed copy). A record of an
 * older version, with the folder, reads the same. */
std::string taskRecord(const std::string& joinedCommand)
{
	const size_t space = joinedCommand.find(' ');
	const std::string program = joinedCommand.substr(0, space);
	const std::string rest = space == std::string::npos ? std::string() : joinedCommand.substr(space);
	return fs::path(program).filename().string() + rest;
}

/** The program on the PATH, or the bare name (its run then fails clearly). */
std::string onPath(const std::string& program)
{
	const char* path = std::getenv("PATH");
	std::stringstream dirs(path ? path : "/usr/bin");
	for (std::string dir; std::getline(dirs, dir, ':');)
		if (!dir.empty() && fs::exists(fs::path(dir) / program)) return (fs::path(dir) / program).string();
	return program;
}

/** rbpf-slam's configuration for one run: its outputs into the task's folder. */
void writePeerIni(const BatchPlan& plan, const Task& task)
{
	std::ifstream in(plan.rbpfSlamIni);
	std::ofstream out(task.dir + "/rbpf-slam.ini");
	for (std::string line; std::getline(in, line);)
		out << (line.rfind("logOutput_dir", 0) == 0 ? "logOutput_dir = " + task.dir + "/out" : line) << "\n";
	if (!out) throw InputError("cannot write '" + task.dir + "/rbpf-slam.ini'");
}

/** rbpf-slam's path (log_estimated_path.txt: step x y z phi ... time in
 * column 8) against the truth, after SE(2) alignment (it starts at its
 * own origin). */
Metrics scorePeer(const BatchPlan& plan, const Task& task, double wallSeconds, double peakMiB)
{
	std::ifstream in(task.dir + "/out/log_estimated_path.txt");
	Trajectory path;
	for (std::string line; std::getline(in, line);)
	{
		std::istringstream row(line);
		std::vector<double> v{std::istream_iterator<double>(row), {}};
		if (v.size() >= 8) path.push_back({v[7], {v[1], v[2], v[4]}});
	}
	if (path.empty()) throw InputError("rbpf-slam wrote no path in '" + task.dir + "/out'");
	writeTumTrajectory(task.dir + "/rbpf-slam.tum", path);
	TAteOptions aligned;
	aligned.align = true;
	const AteStats ate = computeAte(path, readTrajectory(plan.groundTruthOf(plan.scenarios[task.scenario], task.seed)), aligned);
	return {{"ate_aligned_rmse", ate.rmse}, {"ate_aligned_mean", ate.mean}, {"ate_aligned_median", ate.median},
		{"wall_s", wallSeconds}, {"peak_mib", peakMiB}};
}

/** The simulator overrides with {seed} replaced by the seed. */
std::vector<std::string> withSeed(const std::vector<std::string>& set, int seed)
{
	std::vector<std::string> out;
	for (std::string kv : set)
	{
		for (size_t at; (at = kv.find("{seed}")) != std::string::npos;) kv.replace(at, 6, std::to_string(seed));
		out.push_back(kv);
	}
	return out;
}
}  // namespace

std::vector<std::string> taskCommand(const BatchPlan& plan, const Task& task, const std::string& binDir)
{
	const Scenario& s = plan.scenarios[task.scenario];
	const std::string seed = std::to_string(task.seed);
	std::vector<std::string> args;
	if (task.kind == Task::Kind::Render)
	{
		args = {binDir + "/vslam-simul", s.simulIni, plan.rawlogOf(s, task.seed), "--quiet", "--set",
			"vslam_simul.seed=" + seed};
		for (const auto& kv : withSeed(s.simulSet, task.seed)) args.insert(args.end(), {"--set", kv});
		return args;
	}
	if (task.kind == Task::Kind::Peer) return {onPath("rbpf-slam"), task.dir + "/rbpf-slam.ini", plan.rawlogOf(s, task.seed)};
	args = {binDir + "/vslam", s.vslamIni, plan.rawlogOf(s, task.seed), "--out", task.dir + "/vslam", "--quiet",
		"--set", "vslam.RANDOM_SEED=" + seed, "--set", "vslam.ground_truth_file=" + plan.groundTruthOf(s, task.seed)};
	for (const auto& list : {s.vslamSet, plan.variations[task.variation].set})
		for (const auto& kv : list) args.insert(args.end(), {"--set", kv});
	return args;
}

Metrics readMetrics(const std::string& file)
{
	Metrics m;
	std::ifstream in(file);
	std::string key, value;
	while (in >> key >> value) m[key] = std::strtod(value.c_str(), nullptr);  // also "inf", "nan"
	return m;
}

TaskOutcome runTask(const BatchPlan& plan, const Task& task, const std::string& binDir)
{
	const std::vector<std::string> command = taskCommand(plan, task, binDir);
	const std::string doneFile = task.dir + "/done", logFile = task.dir + "/log.txt";
	TaskOutcome outcome;
	const Metrics old = readMetrics(task.dir + "/metrics.txt");
	const bool scored = task.kind != Task::Kind::Run || (old.count("wall_s") && old.count("peak_mib"));
	const std::string record = taskRecord(joined(command));
	if (scored && fs::exists(doneFile) && taskRecord(readText(doneFile)) == record + "\n")
	{
		outcome.ok = outcome.skipped = true;
		outcome.message = "done before";
		const bool stale = task.kind == Task::Kind::Run &&
			(!old.count("scoring_version") || old.at("scoring_version") != kScoringVersion);
		if (!stale) return outcome;
		try
		{
			writeMetrics(task.dir + "/metrics.txt", scoreRun(plan, task, old.at("wall_s"), old.at("peak_mib")));
			outcome.message = "done before, scored again";
		}
		catch (const std::exception& e)
		{
			return {false, false, std::string("scoring failed: ") + e.what()};
		}
		return outcome;
	}
	std::error_code ec;
	fs::remove_all(task.dir, ec);  // a partial or different earlier attempt
	fs::create_directories(task.dir, ec);
	if (ec) return {false, false, "cannot create '" + task.dir + "': " + ec.message()};
	std::ofstream(logFile) << joined(command) << "\n";
	try
	{
		if (task.kind == Task::Kind::Peer) writePeerIni(plan, task);
	}
	catch (const std::exception& e)
	{
		return {false, false, e.what()};
	}
	const ProcessResult process = runProcess(command, logFile);
	if (!process.ok()) return {false, false, process.describe() + ", see " + logFile};
	if (task.kind == Task::Kind::Peer)
	{
		try
		{
			const Metrics m = scorePeer(plan, task, process.wallSeconds, process.peakMiB);
			writeMetrics(task.dir + "/metrics.txt", m);
			char line[120];
			std::snprintf(line, sizeof line, "rbpf-slam ATE mean %.3f m (aligned), %.1f s", m.at("ate_aligned_mean"), process.wallSeconds);
			outcome.message = line;
		}
		catch (const std::exception& e)
		{
			return {false, false, std::string("scoring failed: ") + e.what()};
		}
	}
	else if (task.kind == Task::Kind::Run)
	{
		try
		{
			const Metrics m = scoreRun(plan, task, process.wallSeconds, process.peakMiB);
			writeMetrics(task.dir + "/metrics.txt", m);
			char line[160];
			std::snprintf(line, sizeof line, "ATE %.3f m (odometry %.3f m), %.1f s", m.at("ate_rmse"),
				m.at("odometry_ate_rmse"), process.wallSeconds);
			outcome.message = line;
		}
		catch (const std::exception& e)
		{
			return {false, false, std::string("scoring failed: ") + e.what()};
		}
	}
	else
	{
		// What a rendering needed: vslam-batch --slurm asks the cluster for it.
		writeMetrics(task.dir + "/metrics.txt", {{"wall_s", process.wallSeconds}, {"peak_mib", process.peakMiB}});
		outcome.message = "rendered in " + std::to_string(int(process.wallSeconds)) + " s";
	}
	std::ofstream(doneFile) << record << "\n";
	outcome.ok = true;
	return outcome;
}
}  // namespace vslam::batch

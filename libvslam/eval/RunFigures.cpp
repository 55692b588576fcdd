#include <libvslam/core/InputError.h>
#include <libvslam/eval/AbsoluteTrajectoryError.h>
#include <libvslam/eval/Charts.h>
#include <libvslam/eval/Median.h>
#include <libvslam/eval/RunFigures.h>
#include <libvslam/eval/TrajectoryPlot.h>
#include <libvslam/io/LandmarkMapFile.h>
#include <libvslam/io/NumericTable.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace vslam
{
namespace
{
constexpr std::array<uint8_t, 3> kEstimateRgb{0, 60, 220}, kOdometryRgb{220, 0, 0}, kTruthRgb{0, 160, 0};

/** Position error over time (s since the truth starts) of a trajectory. */
ChartSeries errorSeries(const Trajectory& path, const RunFigureSources& src, double t0,
	const std::array<uint8_t, 3>& rgb, const std::string& label, const se2::Pose& alignment)
{
	Trajectory moved = path;
	for (auto& p : moved) p.pose = se2::compose(alignment, p.pose);
	TAteOptions o;
	o.maxGap = src.maxGap;
	const AteStats s = computeAte(moved, *src.truth, o);
	ChartSeries series;
	series.rgb = rgb;
	series.label = label;
	for (size_t i = 0; i < s.errors.size(); i++)
	{
		series.x.push_back(s.times[i] - t0);
		series.y.push_back(s.errors[i]);
	}
	return series;
}

/** The step log's columns by name (the header line names them). */
struct StepLog
{
	std::vector<std::string> names;
	std::vector<std::vector<double>> rows;

	std::vector<double> column(const std::string& name, const std::string& file) const
	{
		const auto it = std::find(names.begin(), names.end(), name);
		if (it == names.end()) throw InputError("'" + file + "' has no column '" + name + "'");
		std::vector<double> v;
		for (const auto& r : rows) v.push_back(r.at(size_t(it - names.begin())));
		return v;
	}
};

StepLog readStepLog(const std::string& file)
{
	StepLog log;
	std::ifstream in(file);
	std::string header;
	if (!in || !std::getline(in, header)) throw InputError("cannot read '" + file + "'");
	std::istringstream words(header);
	for (std::string w; words >> w;)
		if (w != "%") log.names.push_back(w);
	log.rows = readNumericTable(file, "%", log.names.size());
	return log;
}
}  // namespace

std::vector<size_t> truthJumps(const Trajectory& truth)
{
	std::vector<double> steps;
	for (size_t i = 1; i < truth.size(); i++)
		steps.push_back(std::hypot(truth[i].pose.x - truth[i - 1].pose.x, truth[i].pose.y - truth[i - 1].pose.y));
	const double typical = median(steps);
	std::vector<size_t> jumps;
	for (size_t i = 1; i < truth.size(); i++)
		if (steps[i - 1] > 0.5 && steps[i - 1] > 20 * typical) jumps.push_back(i);
	return jumps;
}

void writePathsFigure(const RunFigureSources& src, const std::vector<se2::Pose>& landmarks, const std::string& pngFile)
{
	const bool aligned = src.alignment.x != 0 || src.alignment.y != 0 || src.alignment.phi != 0;
	Trajectory estimate = *src.estimate;
	for (auto& p : estimate) p.pose = se2::compose(src.alignment, p.pose);
	std::vector<PlotSeries> paths;
	if (src.odometry) paths.push_back({src.odometry, kOdometryRgb, "odometry", {}});
	paths.push_back({src.truth, kTruthRgb, "ground truth", truthJumps(*src.truth)});
	paths.push_back({&estimate, kEstimateRgb, aligned ? "estimate (aligned)" : "estimate", {}});
	writeTrajectoryPlot(src.plan, paths, pngFile, landmarks);
}

std::vector<std::string> writeRunFigures(const RunFigureSources& src, const std::string& folder)
{
	std::error_code ec;
	std::filesystem::create_directories(folder, ec);
	if (!std::filesystem::is_directory(folder)) throw InputError("cannot create folder '" + folder + "'");
	const auto out = [&](const std::string& name) { return (std::filesystem::path(folder) / name).string(); };
	std::vector<std::string> written;
	const Trajectory& truth = *src.truth;
	const double t0 = truth.empty() || std::isnan(truth.front().t) ? 0.0 : truth.front().t;

	// Kidnaps: true (the truth jumps) and declared by the filter.
	ChartMarkers trueKidnaps{{}, {230, 120, 0}, "kidnap (true)"}, declared{{}, {150, 0, 150}, "kidnap declared"},
		reverted{{}, {0, 150, 150}, "kidnap reverted"};
	const std::vector<size_t> jumps = truthJumps(truth);
	for (const size_t i : jumps) trueKidnaps.x.push_back(truth[i].t - t0);
	StepLog steps;
	const std::string stepFile = src.runDir.empty() ? "" : src.runDir + "/log_filter_steps.txt";
	if (!stepFile.empty())
	{
		steps = readStepLog(stepFile);
		const auto times = steps.column("timestamp", stepFile), flags = steps.column("kidnap_declared", stepFile);
		for (size_t i = 0; i < flags.size(); i++)
			if (flags[i] > 0)
				declared.x.push_back(times[i] - t0);
			else if (flags[i] < 0)
				reverted.x.push_back(times[i] - t0);
	}

	// Fig. 2: the paths and the map.
	std::vector<se2::Pose> landmarks;
	std::vector<uint64_t> measurements;
	if (!src.runDir.empty())
		for (const auto& [key, l] : readLandmarkMap(src.runDir + "/final_map.txt", 0, 0, &measurements))
			landmarks.push_back(se2::compose(src.alignment, {l.mean[0], l.mean[1], l.mean[2]}));
	writePathsFigure(src, landmarks, out("paths.png"));
	written.push_back(out("paths.png"));

	// Fig. 4: position error over time.
	std::vector<ChartSeries> errors;
	if (src.odometry)
		errors.push_back(errorSeries(*src.odometry, src, t0, kOdometryRgb, "odometry", {0, 0, 0}));
	errors.push_back(errorSeries(*src.estimate, src, t0, kEstimateRgb, "estimate", src.alignment));
	TChartOptions o;
	o.title = "Position error over time";
	o.xLabel = "time [s]";
	o.yLabel = "error [m]";
	o.markers = {trueKidnaps, declared, reverted};
	writeLineChart(errors, o, out("error_over_time.png"));
	written.push_back(out("error_over_time.png"));
	if (src.runDir.empty()) return written;

	// Fig. 5: measurements per landmark, in the order of creation.
	TChartOptions bars;
	bars.title = "Measurements per landmark";
	bars.xLabel = "landmark (order of creation)";
	bars.yLabel = "measurements";
	writeBarChart(std::vector<double>(measurements.begin(), measurements.end()), kEstimateRgb, bars,
		out("measurements_per_landmark.png"));
	written.push_back(out("measurements_per_landmark.png"));

	// The particle cloud and the mixture proposal over time.
	std::vector<double> seconds = steps.column("timestamp", stepFile);
	for (auto& t : seconds) t -= t0;
	const std::vector<double> used = steps.column("measurements_used", stepFile);
	const auto timeChart = [&](const std::string& column, const std::string& title, const std::string& yLabel,
							   const std::string& file, bool onlyUpdates) {
		ChartSeries s{{}, {}, kEstimateRgb, ""};
		const std::vector<double> values = steps.column(column, stepFile);
		for (size_t i = 0; i < values.size(); i++)
			if (!onlyUpdates || used[i] > 0) s.x.push_back(seconds[i]), s.y.push_back(values[i]);
		TChartOptions c;
		c.title = title;
		c.xLabel = "time [s]";
		c.yLabel = yLabel;
		c.markers = {trueKidnaps, declared, reverted};
		writeLineChart({s}, c, out(file));
		written.push_back(out(file));
	};
	timeChart("spread_xy", "Particle cloud spread (position std. dev.)", "spread [m]", "particle_spread.png", false);
	// The proposal's mix is only defined at steps with measurements.
	timeChart("dual_ratio", "Share of dual particles in the mixture proposal (steps with measurements)",
		"dual ratio", "dual_ratio.png", true);
	return written;
}
}  // namespace vslam

/** vslam-eval: trajectory error of an estimate against ground truth (Sturm
 * et al. 2012 conventions, planar): ATE raw and after SE(2) alignment, RPE
 * over time or distance windows, the error over time as CSV, and the
 * paper's figures for a run. See kUsage. */
#include <libvslam/app/ToolArguments.h>
#include <libvslam/core/InputError.h>
#include <libvslam/eval/AbsoluteTrajectoryError.h>
#include <libvslam/eval/MapError.h>
#include <libvslam/eval/RelativePoseError.h>
#include <libvslam/eval/RunFigures.h>
#include <libvslam/eval/ScenePicture.h>
#include <libvslam/world/FloorPlanFile.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <string>

namespace
{
const char* kUsage =
	"Usage: vslam-eval ESTIMATE GROUND_TRUTH [options]\n"
	"       vslam-eval --run VSLAM_OUTPUT_DIR GROUND_TRUTH [options]\n"
	"  ESTIMATE, GROUND_TRUTH: TUM (timestamp x y z qx qy qz qw), rbpf-slam's\n"
	"  log_estimated_path.txt (step x y z yaw pitch roll timestamp), or (ground truth)\n"
	"  an MRPT per-step pose list (x y z yaw pitch roll); detected per file. Ground\n"
	"  truth is interpolated at the estimate's timestamps (matched by step for pose lists).\n"
	"  --run DIR: the estimate is DIR/estimated_path.tum, the odometry DIR/odometry_path.tum,\n"
	"     and the figures go to DIR/figures/ (unless --figures says otherwise).\n"
	"Prints ATE (RMSE, mean, median, max, heading RMSE) raw and after SE(2) alignment,\n"
	"then after the best similarity (SE(2) and a scale: how much of the error a map\n"
	"built too large or too small explains; the scale maps the estimate onto the truth),\n"
	"and RPE (translation, rotation, drift as % of distance) per window; the same for\n"
	"the odometry if given. Options:\n"
	"  --align             the aligned ATE first (and the figures and CSV aligned)\n"
	"  --max-gap S         largest ground-truth gap to interpolate across (default 0.5 s)\n"
	"  --from S, --to S    score only the poses S seconds or more after the estimate's\n"
	"                      first (--from) and before S seconds after it (--to): e.g. a\n"
	"                      run's exploration and what follows it, each aligned on its own\n"
	"  --rpe-time S        RPE window in seconds (default 1; repeatable)\n"
	"  --rpe-distance M    RPE window in metres travelled (repeatable)\n"
	"  --odometry PATH     dead reckoning to evaluate and draw beside the estimate\n"
	"  --csv FILE          the error over time: series,t,error_xy_m,error_heading_deg\n"
	"  --plot FILE.png     the paths only (estimate, truth, odometry) over the floor plan\n"
	"  --figures DIR       the paper's figures: paths, error over time, and with --run\n"
	"                      measurements per landmark, particle spread, dual ratio\n"
	"  --world WORLD_FILE  a vslam-simul world file: its floor plan under the paths\n"
	"  --landmarks FILE    true landmarks (a simulator's or mrclam2rawlog's _landmarks.txt):\n"
	"                      the map's error, landmarks matched by ID, raw and in the\n"
	"                      trajectory's SE(2) alignment\n"
	"  --map FILE          the estimated map (default with --run: DIR/final_map.txt)\n"
	"  --scene-png FILE    with --run: DIR/final_map.3Dscene drawn offscreen, as\n"
	"                      SceneViewer3D shows it from above\n";

double positiveNumber(const std::string& option, const char* text)
{
	const double v = vslam::numberArgument(option, text);
	if (!(v > 0)) throw std::invalid_argument(option + " needs a positive number, not '" + text + "'");
	return v;
}

void printAte(const std::string& prefix, const vslam::AteStats& s, const vslam::TAteOptions& o)
{
	const char* name = !o.align ? "ate" : o.alignScale ? "ate_sim2_aligned" : "ate_se2_aligned";
	std::printf("%s%s: poses %zu rmse %.4f mean %.4f median %.4f max %.4f heading_rmse_deg %.3f", prefix.c_str(),
		name, s.associated, s.rmse, s.mean, s.median, s.max, s.headingRmse * 180 / M_PI);
	if (o.alignScale) std::printf(" scale %.4f", s.alignmentScale);
	std::printf("\n");
}

void printRpe(const std::string& prefix, const vslam::RpeStats& s, const vslam::TRpeOptions& o)
{
	char window[64];
	std::snprintf(window, sizeof window, "%g%s", o.delta, o.window == vslam::TRpeOptions::Window::Time ? "s" : "m");
	std::printf(
		"%srpe_%s: pairs %zu trans_rmse %.4f trans_mean %.4f trans_median %.4f trans_max %.4f "
		"rot_rmse_deg %.3f rot_mean_deg %.3f drift_pct %.2f\n",
		prefix.c_str(), window, s.translation.count, s.translation.rmse, s.translation.mean, s.translation.median,
		s.translation.max, s.rotation.rmse * 180 / M_PI, s.rotation.mean * 180 / M_PI,
		s.meanTravelled > 0 ? 100 * s.translation.mean / s.meanTravelled : 0.0);
}

/** Both ATE lines (the asked-for one first), the one after the best
 * similarity, and the RPE lines; returns the asked-for ATE. */
vslam::AteStats report(const std::string& prefix, const vslam::Trajectory& estimate, const vslam::Trajectory& truth,
	vslam::TAteOptions o, const std::vector<vslam::TRpeOptions>& windows)
{
	const vslam::AteStats asked = vslam::computeAte(estimate, truth, o);
	if (asked.associated == 0)
		throw vslam::InputError(
			(prefix.empty() ? "the estimate" : "the odometry") + std::string(": no pose has ground truth at its time"));
	printAte(prefix, asked, o);
	o.align = !o.align;
	printAte(prefix, vslam::computeAte(estimate, truth, o), o);
	o.align = o.alignScale = true;
	printAte(prefix, vslam::computeAte(estimate, truth, o), o);
	for (auto w : windows)
	{
		w.maxGap = o.maxGap;
		printRpe(prefix, vslam::computeRpe(estimate, truth, w), w);
	}
	return asked;
}

void printMapError(const std::string& name, const vslam::MapErrorStats& m)
{
	std::printf("%s: landmarks %zu true %zu matched %zu rmse %.4f mean %.4f median %.4f max %.4f heading_rmse_deg %.3f\n",
		name.c_str(), m.estimated, m.truth, m.matched, m.position.rmse, m.position.mean, m.position.median,
		m.position.max, m.headingRmse * 180 / M_PI);
}

void writeErrorCsv(const std::string& file, const std::vector<std::pair<std::string, vslam::AteStats>>& series)
{
	FILE* f = std::fopen(file.c_str(), "wt");
	if (!f) throw vslam::InputError("cannot create '" + file + "'");
	std::fprintf(f, "series,t,error_xy_m,error_heading_deg\n");
	for (const auto& [name, s] : series)
		for (size_t i = 0; i < s.errors.size(); i++)
			std::fprintf(f, "%s,%.6f,%.6f,%.4f\n", name.c_str(), s.times[i], s.errors[i],
				s.headingErrors[i] * 180 / M_PI);
	if (std::fclose(f) != 0) throw vslam::InputError("cannot write '" + file + "'");
}

/** The command line. A mistake throws std::invalid_argument. */
struct EvalCommand
{
	bool help = false;
	vslam::TAteOptions ate;
	double from = 0, to = std::numeric_limits<double>::infinity();
	std::vector<vslam::TRpeOptions> windows;
	std::vector<std::string> files;  //!< estimate, ground truth
	std::string runDir, csvFile, plotFile, figuresDir, odometryFile, worldFile, trueMapFile, mapFile, scenePng;
};

EvalCommand parseCommand(int argc, const char** argv)
{
	using vslam::TRpeOptions;
	EvalCommand c;
	for (int i = 1; i < argc; i++)
	{
		const std::string a = argv[i];
		const bool hasValue = i + 1 < argc;
		std::string* file = a == "--run" ? &c.runDir
			: a == "--csv"                ? &c.csvFile
			: a == "--plot"               ? &c.plotFile
			: a == "--figures"            ? &c.figuresDir
			: a == "--odometry"           ? &c.odometryFile
			: a == "--world"              ? &c.worldFile
			: a == "--landmarks"          ? &c.trueMapFile
			: a == "--map"                ? &c.mapFile
			: a == "--scene-png"          ? &c.scenePng
										  : nullptr;
		if (a == "--help" || a == "-h")
			c.help = true;
		else if (a == "--align")
			c.ate.align = true;
		else if (file && hasValue)
			*file = argv[++i];
		else if (a == "--max-gap" && hasValue)
			c.ate.maxGap = positiveNumber(a, argv[++i]);
		else if (a == "--from" && hasValue)
			c.from = vslam::numberArgument(a, argv[++i]);
		else if (a == "--to" && hasValue)
			c.to = positiveNumber(a, argv[++i]);
		else if ((a == "--rpe-time" || a == "--rpe-distance") && hasValue)
		{
			TRpeOptions w;
			w.window = a == "--rpe-time" ? TRpeOptions::Window::Time : TRpeOptions::Window::Distance;
			w.delta = positiveNumber(a, argv[++i]);
			c.windows.push_back(w);
		}
		else if (a.rfind("--", 0) == 0)
			throw std::invalid_argument("unknown option '" + a + "' (or its value is missing)");
		else
			c.files.push_back(a);
	}
	if (c.help) return c;
	if (!c.runDir.empty())
	{
		if (c.files.size() != 1) throw std::invalid_argument("expected --run DIR GROUND_TRUTH");
		c.files.insert(c.files.begin(), c.runDir + "/estimated_path.tum");
		if (c.odometryFile.empty() && std::filesystem::exists(c.runDir + "/odometry_path.tum"))
			c.odometryFile = c.runDir + "/odometry_path.tum";
		if (c.figuresDir.empty()) c.figuresDir = c.runDir + "/figures";
		if (c.mapFile.empty()) c.mapFile = c.runDir + "/final_map.txt";
	}
	if (c.files.size() != 2) throw std::invalid_argument("expected ESTIMATE GROUND_TRUTH");
	if (!c.scenePng.empty() && c.runDir.empty()) throw std::invalid_argument("--scene-png needs --run DIR");
	if (c.windows.empty()) c.windows.push_back(TRpeOptions());  // 1 s, as the TUM tools
	if (!(c.from < c.to)) throw std::invalid_argument("--from must be before --to");
	if (!c.trueMapFile.empty() && c.mapFile.empty()) throw std::invalid_argument("--landmarks needs --map FILE (or --run)");
	return c;
}

/** The figures and pictures asked for. */
void writeFigures(const EvalCommand& c, const vslam::Trajectory& estimate, const vslam::Trajectory& truth,
	const std::optional<vslam::Trajectory>& odometry, const vslam::AteStats& s)
{
	using namespace vslam;
	std::optional<world::FloorPlan> plan;
	if (!c.worldFile.empty()) plan = world::loadFloorPlan(c.worldFile, "/usr/share");
	RunFigureSources src;
	src.estimate = &estimate;
	src.truth = &truth;
	src.odometry = odometry ? &*odometry : nullptr;
	src.plan = plan ? &*plan : nullptr;
	src.runDir = c.runDir;
	src.alignment = s.alignment;
	src.maxGap = c.ate.maxGap;
	if (!c.plotFile.empty()) writePathsFigure(src, {}, c.plotFile);
	if (!c.figuresDir.empty())
		for (const auto& f : writeRunFigures(src, c.figuresDir)) std::printf("figure: %s\n", f.c_str());
	if (!c.scenePng.empty()) writeScenePicture(c.runDir + "/final_map.3Dscene", c.scenePng);
}

void evaluate(const EvalCommand& c)
{
	using namespace vslam;
	const Trajectory whole = readTrajectory(c.files[0]), truth = readTrajectory(c.files[1]);
	const double t0 = whole.empty() ? 0 : whole.front().t;
	const Trajectory estimate = timeWindow(whole, t0, c.from, c.to);
	if (estimate.empty() && !whole.empty()) throw InputError("'" + c.files[0] + "': no pose between --from and --to");
	const AteStats s = report("", estimate, truth, c.ate, c.windows);
	std::vector<std::pair<std::string, AteStats>> csv{{"estimate", s}};
	std::optional<Trajectory> odometry;
	if (!c.odometryFile.empty())
	{
		odometry = timeWindow(readTrajectory(c.odometryFile), t0, c.from, c.to);
		TAteOptions raw = c.ate;
		raw.align = false;  // odometry starts where the truth does
		csv.push_back({"odometry", report("odometry_", *odometry, truth, raw, c.windows)});
	}
	if (!c.csvFile.empty()) writeErrorCsv(c.csvFile, csv);
	if (!c.trueMapFile.empty())
	{
		const LandmarkMap map = readLandmarkMap(c.mapFile, 0, 0), trueMap = readLandmarkMap(c.trueMapFile, 0, 0);
		TAteOptions align = c.ate;
		align.align = true;
		printMapError("map", computeMapError(map, trueMap));
		printMapError("map_se2_aligned", computeMapError(map, trueMap, computeAte(estimate, truth, align).alignment));
	}
	writeFigures(c, estimate, truth, odometry, s);
}
}  // namespace

int main(int argc, const char** argv)
{
	try
	{
		const EvalCommand c = parseCommand(argc, argv);
		if (c.help)
		{
			std::cout << kUsage;
			return 0;
		}
		evaluate(c);
		return 0;
	}
	catch (const std::invalid_argument& e)
	{
		std::cerr << "vslam-eval: error: " << e.what() << "\n" << kUsage;
		return 1;
	}
	catch (const std::exception& e)
	{
		std::cerr << "vslam-eval: error: " << e.what() << "\n";
		return 3;
	}
}

#include <libvslam/app/CVSlamApp.h>
#include <libvslam/app/InterruptFlag.h>
#include <libvslam/app/KeyframesAlongOdometry.h>
#include <libvslam/app/RunMap.h>
#include <libvslam/app/RunOutputFolder.h>
#include <libvslam/config/ConfigError.h>
#include <libvslam/config/ConfigReference.h>
#include <libvslam/config/IniText.h>
#include <libvslam/config/KeyValidation.h>
#include <libvslam/config/Overrides.h>
#include <libvslam/config/StrictRead.h>
#include <libvslam/core/ActionOdometry.h>
#include <libvslam/core/AllottedCpus.h>
#include <libvslam/core/ExceptionText.h>
#include <libvslam/core/InputError.h>
#include <libvslam/core/NumericalError.h>
#include <libvslam/core/OutputError.h>
#include <libvslam/eval/GroundTruthCheck.h>
#include <libvslam/filter/CVSlamParticleFilter.h>
#include <libvslam/filter/ParticleLandmarkMap.h>
#include <libvslam/frontend/ImageBufferAllocation.h>
#include <libvslam/frontend/ImagesToMeasurements.h>
#include <libvslam/io/COutputFile.h>
#include <libvslam/io/CPathFileWriter.h>
#include <libvslam/io/CRawlogReader.h>
#include <libvslam/io/LandmarkMapFile.h>
#include <libvslam/io/RunScene.h>
#include <libvslam/io/Trajectory.h>
#include <libvslam/io/VSlamMapFile.h>
#include <libvslam/world/FloorPlanFile.h>
#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/system/datetime.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

using namespace vslam;
namespace fs = std::filesystem;

std::string CVSlamApp::usage()
{
	return "Usage: vslam CONFIG.ini [RAWLOG] [--out DIR] [--set SECTION.KEY=VALUE ...]\n"
		   "             [--quiet]\n"
		   "       vslam --print-default-config [--markdown] | --help | --version\n"
		   "\n"
		   "Runs the vSLAM particle filter (Karlsson et al. 2005) over an MRPT rawlog\n"
		   "(actions/sensory-frames or observations format, plain or gzip).\n"
		   "  RAWLOG          overrides [vslam] rawlog_file\n"
		   "  --out DIR       overrides [vslam] output_dir\n"
		   "  --set S.K=V     overrides any INI key (repeatable)\n"
		   "  --quiet         no progress line\n"
		   "Exit codes: 0 ok, 1 usage, 2 configuration error, 3 bad input data,\n"
		   "            4 other error, 130 interrupted (outputs so far are kept).\n";
}

std::string CVSlamApp::defaultConfigText()
{
	mrpt::config::CConfigFileMemory c;
	CVSlamApp::TOptions().saveToConfigFile(c, CVSlamApp::TOptions::kSection);
	CVSlamParticleFilter::TOptions().saveToConfig(c);
	CVisualFrontEnd::TOptions().saveToConfig(c);
	std::string text;
	c.getContent(text);
	return text;
}

std::vector<config::NumericKey> CVSlamApp::numericKeys()
{
	config::NumericKeyRecorder recorder;
	const mrpt::config::CConfigFileMemory none;  // every key at its default
	CVSlamApp::TOptions().loadFromConfigFile(none, CVSlamApp::TOptions::kSection);
	CVSlamParticleFilter::TOptions().loadFromConfig(none);
	CVisualFrontEnd::TOptions().loadFromConfig(none);
	return recorder.keys();
}

config::KnownKeys CVSlamApp::knownKeys()
{
	config::KnownKeys known;
	known.addFromOptions(CVSlamApp::TOptions(), CVSlamApp::TOptions::kSection);
	CVSlamParticleFilter::TOptions().registerKnownKeys(known);
	CVisualFrontEnd::TOptions().registerKnownKeys(known);
	return known;
}

std::string CVSlamApp::resolveInput(const std::string& path) const
{
	if (path.empty() || fs::path(path).is_absolute()) return path;
	return (fs::path(m_configFile).parent_path() / path).lexically_normal().string();
}

namespace
{
bool hasImages(const mrpt::obs::CSensoryFrame& sf)
{
	for (const auto& o : sf)
		if (std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(o)) return true;
	return false;
}
}  // namespace

void CVSlamApp::loadConfig(const std::string& file, const std::vector<std::string>& overrides)
{
	const std::string text = config::readIniFile(file);
	std::vector<config::Override> parsed;
	for (const auto& o : overrides) parsed.push_back(config::parseOverride(o));
	params = config::parseIniWithOverrides(text, parsed);

	config::checkNoUnknownKeys(params, knownKeys());
	appOptions.loadFromConfigFile(params, CVSlamApp::TOptions::kSection);
	filterOptions.loadFromConfig(params);
	frontEndOptions.loadFromConfig(params);
	frontEndOptions.takeOdometryNoiseFrom(filterOptions.motion.sigma_T);
}

bool CVSlamApp::initialize(int argc, const char** argv)
{
	std::vector<std::string> positional, overrides;
	std::string outDir;
	for (int i = 1; i < argc; i++)
	{
		const std::string a = argv[i];
		const auto value = [&](const char* opt) {
			if (i + 1 >= argc) throw std::invalid_argument(std::string(opt) + " needs a value");
			return std::string(argv[++i]);
		};
		if (a == "--help" || a == "-h")
		{
			std::cout << usage();
			return false;
		}
		if (a == "--version")
		{
			std::cout << "vslam 0.1.0\n";
			return false;
		}
		if (a == "--print-default-config")
		{
			// --markdown: the configuration reference (doc/configuration.md).
			const bool markdown = i + 1 < argc && std::string(argv[i + 1]) == "--markdown";
			std::cout << (markdown ? config::markdownReference(defaultConfigText(), numericKeys()) : defaultConfigText());
			return false;
		}
		if (a == "--out")
			outDir = value("--out");
		else if (a == "--set")
			overrides.push_back(value("--set"));
		else if (a.rfind("--set=", 0) == 0)
			overrides.push_back(a.substr(6));
		else if (a == "--quiet")
			m_quiet = true;
		else if (a.rfind("--", 0) == 0)
			throw std::invalid_argument("unknown option '" + a + "'");
		else
			positional.push_back(a);
	}
	if (positional.empty() || positional.size() > 2)
		throw std::invalid_argument("expected CONFIG.ini [RAWLOG]");
	m_configFile = positional[0];
	try
	{
		loadConfig(m_configFile, overrides);
	}
	catch (const ConfigError& e)
	{
		throw ConfigError("configuration '" + m_configFile + "'" +
			(overrides.empty() ? "" : " (with --set overrides)") + ": " + e.what());
	}
	m_rawlogFile = positional.size() == 2 ? positional[1] : resolveInput(appOptions.rawlog_file);
	if (m_rawlogFile.empty())
		throw ConfigError("configuration '" + m_configFile +
			"': no rawlog: give it on the command line or set [vslam] rawlog_file");
	m_groundTruthFile = resolveInput(appOptions.ground_truth_file);
	m_priorMapFile = resolveInput(appOptions.prior_map_file);
	const std::string configName = "configuration '" + m_configFile + "': ";
	if (appOptions.localization_only && m_priorMapFile.empty())
		throw ConfigError(configName + "[vslam] localization_only = true needs [vslam] prior_map_file (the map to localize in)");
	if (appOptions.initial_pose_unknown && m_priorMapFile.empty())
		throw ConfigError(configName + "[vslam] initial_pose_unknown = true needs [vslam] prior_map_file (the map to find the robot in)");
	if (appOptions.initial_pose_unknown && appOptions.initial_pose_from_ground_truth)
		throw ConfigError(configName + "[vslam] initial_pose_unknown and initial_pose_from_ground_truth exclude each other");
	if (appOptions.initial_pose_unknown && !filterOptions.kidnap.enabled)
		throw ConfigError(configName + "[vslam] initial_pose_unknown = true needs [vslam_kidnap] enabled = true (its "
			"relocalization hypothesis finds the pose)");
	m_outputDir = outDir.empty() ? appOptions.output_dir : outDir;
	if (m_quiet) appOptions.show_progress = false;
	return true;
}

namespace
{
/** Progress on stderr: one updating line on a terminal, a line per 10%
 * otherwise. */
class ProgressReporter
{
   public:
	explicit ProgressReporter(bool enabled) : m_enabled(enabled), m_tty(isatty(2)) {}
	void update(double fraction, size_t steps, size_t landmarks, double ess)
	{
		if (!m_enabled) return;
		const auto now = std::chrono::steady_clock::now();
		const bool due = m_tty ? now - m_last > std::chrono::milliseconds(500)
							   : fraction >= m_nextMark;
		if (!due) return;
		m_last = now;
		while (m_nextMark <= fraction) m_nextMark += 0.1;
		std::fprintf(stderr, "%s[vslam] %5.1f%%  step %zu  landmarks %zu  ESS %.2f%s",
			m_tty ? "\r" : "", 100 * fraction, steps, landmarks, ess, m_tty ? "   " : "\n");
		std::fflush(stderr);
	}
	void finish()
	{
		if (m_enabled && m_tty) std::fprintf(stderr, "\n");
	}

   private:
	bool m_enabled, m_tty;
	double m_nextMark = 0.1;
	std::chrono::steady_clock::time_point m_last{};
};

double toSeconds(mrpt::Clock::time_point t) { return mrpt::Clock::toDouble(t); }

/** The message of a caught exception, for the summary. */
std::string failureText(const std::exception_ptr& failure)
{
	try
	{
		std::rethrow_exception(failure);
	}
	catch (const std::bad_alloc&)
	{
		return "out of memory";
	}
	catch (const std::exception& e)
	{
		return exceptionText(e);
	}
	catch (...)
	{
		return "unknown error";
	}
}

/** The files written step by step, each row flushed. */
struct StepOutputs
{
	CPathFileWriter rbpf, tum, odometry, odometryTum, smoothed;
	COutputFile stepLog;

	StepOutputs(const RunOutputFolder& folder, const std::string& runId)
		: rbpf(folder.file("log_estimated_path.txt"), CPathFileWriter::Format::RbpfSlam),
		  tum(folder.file("estimated_path.tum"), CPathFileWriter::Format::Tum, runId),
		  odometry(folder.file("log_odometry_path.txt"), CPathFileWriter::Format::RbpfSlamOdometry),
		  odometryTum(folder.file("odometry_path.tum"), CPathFileWriter::Format::Tum, runId),
		  smoothed(folder.file("smoothed_path.tum"), CPathFileWriter::Format::Tum, runId),
		  stepLog(folder.file("log_filter_steps.txt"), COutputFile::Mode::Streamed)
	{
		stepLog.print(
			"%% step timestamp ESS dual_ratio dual_particles explained_fraction "
			"hypothesis_support kidnap_declared landmarks measurements_used step_ms spread_xy spread_phi_deg\n");
		stepLog.print("%% vslam run %s\n", runId.c_str());
		stepLog.flush();
	}
	void close()
	{
		for (auto* w : {&rbpf, &tum, &odometry, &odometryTum, &smoothed}) w->close();
		stepLog.commit();
	}
};

/** The noise and spread keys the configuration sets away from their
 * defaults: the likely cause of a filter state that stopped being finite. */
std::string likelyNumericalCause(const mrpt::config::CConfigFileBase& params)
{
	std::string keys;
	for (const auto& k : CVSlamApp::numericKeys())
	{
		const bool noise = k.key.find("std") != std::string::npos || k.key.find("sigma") != std::string::npos;
		if (!noise || !params.keyExists(k.section, k.key)) continue;
		const std::string value = config::rawValue(params, k.section, k.key);
		if (std::strtod(value.c_str(), nullptr) == k.defaultValue) continue;
		keys += (keys.empty() ? "" : ", ") + ("[" + k.section + "] " + k.key + " = " + value);
	}
	return keys.empty() ? "no noise key differs from its default" : "likely cause: " + keys;
}

/** Throws NumericalError if the filter's weights, mean or covariance are no
 * longer finite: every output after that would be NaN. */
void checkFilterIsFinite(const CVSlamParticleFilter& filter, uint64_t step, const mrpt::config::CConfigFileBase& params)
{
	const se2::Pose mean = filter.meanPose();
	bool finite = std::isfinite(mean.x) && std::isfinite(mean.y) && std::isfinite(mean.phi) &&
		filter.poseCovariance().allFinite();
	for (size_t i = 0; finite && i < filter.particlesCount(); i++)
		finite = !std::isnan(filter.getW(i)) && filter.getW(i) != INFINITY;
	if (!finite)
		throw NumericalError("step " + std::to_string(step) +
			": the filter's state is no longer finite (NaN or infinite weight, pose or covariance); " +
			likelyNumericalCause(params));
}
}  // namespace

/** Everything one run keeps between its steps. */
struct CVSlamApp::RunState
{
	RunState(const RunOutputFolder& folder, const CVSlamParticleFilter::TOptions& options, const std::string& runId)
		: outputs(folder, runId), filter(options), controllerPose(options.smoothedPose), odo(options.pf.initialPose)
	{
		pf.m_options = options.pf.toMrpt();
	}
	StepOutputs outputs;
	CVSlamParticleFilter filter;
	mrpt::bayes::CParticleFilter pf;
	CSmoothedPose controllerPose;  // smoothed_path.tum
	Trajectory estimated, odometry;
	se2::Pose odo;
	std::unique_ptr<CVisualFrontEnd> frontEnd;
	std::shared_ptr<const CVSlamMap> priorMap;
	RunSummary::FrontEnd frontEndSummary;
	double firstT = 0, lastT = 0, stepSumMs = 0;
	double longestGap = 0;  //!< s between two timed steps
	bool anyTimed = false;
};

namespace
{
/** The floor plan vslam-simul wrote beside a rendered rawlog (NAME.rawlog:
 * NAME_world.world) as outlines, or none. One that cannot be read is a
 * warning: the scene is drawn without it. */
std::vector<std::vector<Eigen::Vector2d>> floorPlanBeside(const std::string& rawlogFile)
{
	const fs::path rawlog(rawlogFile);
	const fs::path world = rawlog.parent_path() / (rawlog.stem().string() + "_world.world");
	if (!fs::is_regular_file(world)) return {};
	try
	{
		return world::loadFloorPlan(world.string(), "/usr/share").solidPolygons();
	}
	catch (const std::exception& e)
	{
		std::cerr << "vslam: warning: final_map.3Dscene without the floor plan: " << e.what() << "\n";
		return {};
	}
}

/** What SceneViewer3D shows of the run: its paths, the best particle's map
 * and the floor plan of a rendered rawlog. */
RunSceneContent sceneOf(const Trajectory& estimated, const Trajectory& odometry, const Trajectory& groundTruth,
	const CLandmarkIndex& index, const LandmarkBank& bank, const std::string& rawlogFile)
{
	Trajectory truth;  // over the run's time only (a run may stop before its ground truth ends)
	for (const auto& p : groundTruth)
		if (!estimated.empty() && p.t >= estimated.front().t - 0.5 && p.t <= estimated.back().t + 0.5) truth.push_back(p);
	RunSceneContent c{estimated, odometry, truth, {}, floorPlanBeside(rawlogFile)};
	for (size_t slot = 0; slot < bank.size(); slot++)
	{
		const auto& l = bank[slot];
		c.landmarks.push_back({{l.mean[0], l.mean[1], l.mean[2]}, l.cov.topLeftCorner<2, 2>(),
			index.entry(slot).key.kind == LandmarkKind::Pose});
	}
	return c;
}
}  // namespace

int CVSlamApp::run()
{
	// Inputs are opened and checked before the output folder is touched: a
	// bad rawlog, ground truth or map leaves earlier outputs intact.
	CRawlogReader reader(m_rawlogFile);
	const auto [groundTruth, priorMap] = readInputFiles();
	RawlogStep step;  // read before the filter exists: it may set the start
	bool haveStep = reader.next(step);
	if (appOptions.initial_pose_from_ground_truth) startFromGroundTruth(groundTruth, haveStep, step);
	// Before the output folder is touched, where the first step shows it.
	if (haveStep && step.sf && hasImages(*step.sf)) checkImagesCanBeLocalized(priorMap.get());

	RunSummary summary;
	summary.seed = appOptions.RANDOM_SEED >= 0
		? static_cast<uint64_t>(appOptions.RANDOM_SEED)
		: static_cast<uint32_t>(std::chrono::system_clock::now().time_since_epoch().count());
	// Seed once, before any draw: MRPT 2.5 does not restart its cached
	// Gaussian on a reseed, so a later reseed would not repeat a run.
	mrpt::random::getRandomGenerator().randomize(static_cast<uint32_t>(summary.seed));
	const RunOutputFolder folder(m_outputDir);
	startOutputs(folder, summary);

	std::unique_ptr<RunState> state;
	std::exception_ptr failure;
	const auto fail = [&](std::exception_ptr e) {
		if (failure) return;  // the first failure is the one to report
		failure = e;
		summary.status = "failed";
		summary.error = failureText(failure);
	};
	try
	{
		state = std::make_unique<RunState>(folder, filterOptions, summary.runId);
		if (priorMap) startFromPriorMap(*state, priorMap, summary);
		processSteps(*state, reader, step, haveStep, summary);
		state->outputs.close();
	}
	catch (const std::bad_alloc&)
	{
		fail(std::current_exception());
		state.reset();  // the particles' memory, for the summary to be written
	}
	catch (...)
	{
		fail(std::current_exception());
	}
	if (state)
	{
		summarizeReader(reader, *state, summary);
		try
		{
			writeFinalOutputs(folder, *state, groundTruth, summary);
		}
		catch (...)
		{
			fail(std::current_exception());
		}
	}
	if (summary.status == "running") summary.status = "completed";
	summary.peakMemoryMiB = peakMemoryMiB();
	folder.releaseSummarySpace();
	summary.write(folder.file("run_summary.yaml"), state ? &state->filter : nullptr);
	if (state) std::cerr << summary.brief(state->filter);
	if (!summary.groundTruthWarning.empty()) std::cerr << "vslam: warning: " << summary.groundTruthWarning << "\n";
	std::cerr << "vslam: outputs in " << m_outputDir << "/\n";
	if (failure) std::rethrow_exception(failure);
	return summary.status == "interrupted" ? kInterrupted : kOk;
}

CVSlamApp::InputFiles CVSlamApp::readInputFiles() const
{
	// A file named in the INI names its key when it cannot be read.
	const auto naming = [](const char* key, const auto& read) {
		try
		{
			return read();
		}
		catch (const InputError& e)
		{
			throw InputError(std::string("[vslam] ") + key + ": " + e.what());
		}
	};
	InputFiles in;
	if (!m_groundTruthFile.empty())
		in.groundTruth = naming("ground_truth_file", [&] { return readTrajectory(m_groundTruthFile); });
	if (m_priorMapFile.empty()) return in;
	in.priorMap = naming("prior_map_file", [&] {
		return std::make_shared<const CVSlamMap>(
			readPriorMap(m_priorMapFile, appOptions.prior_map_std_xy, appOptions.prior_map_std_phi));
	});
	if (appOptions.initial_pose_unknown && in.priorMap->estimates.empty())
		throw ConfigError("[vslam] prior_map_file '" + m_priorMapFile + "' holds no landmark to find the robot by");
	return in;
}

void CVSlamApp::startFromPriorMap(RunState& r, std::shared_ptr<const CVSlamMap> map, RunSummary& summary) const
{
	r.priorMap = std::move(map);
	r.filter.setPriorMap(estimatesOf(*r.priorMap), {}, appOptions.localization_only);
	if (!appOptions.initial_pose_unknown) return;
	r.filter.setPoseUnknown();
	summary.startPose = RunSummary::StartPose();
}

void CVSlamApp::checkImagesCanBeLocalized(const CVSlamMap* priorMap) const
{
	if (appOptions.localization_only && priorMap && priorMap->appearances.empty())
		throw ConfigError("[vslam] prior_map_file '" + m_priorMapFile +
			"' holds no visual landmark's appearance, so camera images cannot be localized in it "
			"(localization_only): give the final_map.vslam of a camera run");
}

std::unique_ptr<CVisualFrontEnd> CVSlamApp::makeFrontEnd(const CVSlamMap* priorMap) const
{
	checkImagesCanBeLocalized(priorMap);
	auto frontEnd = std::make_unique<CVisualFrontEnd>(frontEndOptions);
	const std::string key = "[vslam] prior_map_file '" + m_priorMapFile + "'";
	if (priorMap)
	{
		try
		{
			// The odometry starts at the initial pose: its frame is the map's.
			frontEnd->loadMap(*priorMap, mrpt::poses::CPose2D());
		}
		catch (const std::invalid_argument& e)
		{
			throw ConfigError(key + ": " + e.what() + " ([" + CLandmarkDatabase::TOptions::kSection + "])");
		}
	}
	if (appOptions.localization_only) frontEnd->fixMap();
	return frontEnd;
}

void CVSlamApp::startOutputs(const RunOutputFolder& folder, RunSummary& summary) const
{
	// Not the output folder: the same run written elsewhere is the same run.
	summary.runId = makeRunId(effectiveConfigText(summary.seed, ""), m_rawlogFile, summary.seed);
	summary.configFile = m_configFile;
	summary.rawlogFile = m_rawlogFile;
	summary.outputDir = m_outputDir;
	folder.clearEarlierOutputs();
	COutputFile cfg(folder.file("config_used.ini"), COutputFile::Mode::Atomic);
	cfg.write("; the effective configuration of vslam run " + summary.runId +
		" (INI, command line, --set; absolute paths, the seed used): `vslam config_used.ini` reruns it\n" +
		effectiveConfigText(summary.seed, m_outputDir));
	cfg.commit();
	summary.write(folder.file("run_summary.yaml"), nullptr);  // status: running
	folder.reserveSummarySpace();
}

void CVSlamApp::startFromGroundTruth(const Trajectory& groundTruth, bool haveStep, RawlogStep& step)
{
	if (groundTruth.empty())
		throw ConfigError("configuration '" + m_configFile +
			"': initial_pose_from_ground_truth needs [vslam] ground_truth_file");
	const double t0 = haveStep && step.timestamp != INVALID_TIMESTAMP ? toSeconds(step.timestamp) : groundTruth.front().t;
	// The truth must span the rawlog's start: another run's truth would put
	// the robot somewhere it never was.
	const auto p = interpolate(groundTruth, t0, 1e9);
	if (!p && std::abs(t0 - groundTruth.front().t) > 1.0)
		throw ConfigError("[vslam] ground_truth_file '" + m_groundTruthFile + "' spans times " +
			std::to_string(groundTruth.front().t) + " to " + std::to_string(groundTruth.back().t) +
			" s, but rawlog '" + m_rawlogFile + "' starts at " + std::to_string(t0) +
			" s: it is not this rawlog's ground truth (initial_pose_from_ground_truth needs it)");
	filterOptions.pf.initialPose = p ? *p : groundTruth.front().pose;
	// That is the pose at the first step's time, i.e. after the first
	// step's odometry increment (which leads up to it): not applied again.
	step.action.reset();
}

std::string CVSlamApp::effectiveConfigText(uint64_t seed, const std::string& outputDir) const
{
	// Every key as read (directives expanded, overrides applied), with the
	// command line's files and the seed used, paths made absolute.
	const auto absolute = [](const std::string& p) { return p.empty() ? p : fs::absolute(p).lexically_normal().string(); };
	const std::map<std::string, std::string> runKeys = {{"rawlog_file", absolute(m_rawlogFile)},
		{"output_dir", absolute(outputDir)}, {"ground_truth_file", absolute(m_groundTruthFile)},
		{"prior_map_file", absolute(m_priorMapFile)}, {"RANDOM_SEED", std::to_string(seed)}};
	std::vector<std::string> sections;
	params.getAllSections(sections);
	if (std::find(sections.begin(), sections.end(), CVSlamApp::TOptions::kSection) == sections.end())
		sections.insert(sections.begin(), CVSlamApp::TOptions::kSection);
	std::ostringstream text;
	for (const auto& section : sections)
	{
		text << "\n[" << section << "]\n";
		const bool app = section == CVSlamApp::TOptions::kSection;
		std::vector<std::string> keys;
		params.getAllKeys(section, keys);
		for (const auto& key : keys)
			if (!app || !runKeys.count(key)) text << key << " = " << config::rawValue(params, section, key) << "\n";
		if (app)
			for (const auto& [key, value] : runKeys) text << key << " = " << value << "\n";
	}
	return text.str();
}

void CVSlamApp::processSteps(RunState& r, CRawlogReader& reader, RawlogStep& step, bool haveStep, RunSummary& summary)
{
	ProgressReporter progress(appOptions.show_progress);
	InterruptFlag interrupt;
	const auto start = std::chrono::steady_clock::now();
	for (; haveStep; haveStep = reader.next(step))
	{
		if (interrupt.raised())
		{
			summary.status = "interrupted";
			break;
		}
		processStep(r, step, summary);
		summary.steps++;
		progress.update(reader.progress(), summary.steps, r.filter.landmarkIndex().size(), r.filter.ESS());
		if (appOptions.max_steps > 0 && summary.steps >= appOptions.max_steps) break;
	}
	progress.finish();
	summary.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void CVSlamApp::processStep(RunState& r, const RawlogStep& step, RunSummary& summary)
{
	const auto t0 = std::chrono::steady_clock::now();
	const std::string entry = "rawlog '" + m_rawlogFile + "', entry " + std::to_string(step.entry);
	se2::Pose stepIncrement{0, 0, 0};
	if (step.action)
		if (const auto u = odometryIncrement(*step.action))
			stepIncrement = u->asTPose(), r.odo = se2::compose(r.odo, stepIncrement);
	if (hasImages(*step.sf))
	{
		// Camera images: the front-end turns them into measurements.
		if (!r.frontEnd) r.frontEnd = makeFrontEnd(r.priorMap.get());
		const auto m = replaceImagesWithMeasurements(
			*r.frontEnd, *step.sf, mrpt::poses::CPose2D(r.odo.x, r.odo.y, r.odo.phi), entry);
		r.frontEndSummary.images += m.images;
		r.frontEndSummary.measurements += m.measurements;
		r.frontEndSummary.created += m.created;
		r.frontEndSummary.pruned += m.pruned;
	}
	try
	{
		r.pf.executeOn(r.filter, step.action.get(), step.sf.get());
	}
	catch (const std::exception& e)
	{
		// Bad data found by the filter arrives wrapped by MRPT.
		const std::string why = r.filter.takeInputError();
		if (why.empty()) throw;
		throw InputError(entry + ": " + why);
	}
	checkFilterIsFinite(r.filter, summary.steps, params);
	const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
	r.stepSumMs += ms;
	summary.stepMaxMs = std::max(summary.stepMaxMs, ms);

	// A step without a timestamp (e.g. an empty last frame) keeps the
	// previous step's, so the TUM output stays ordered.
	const bool timed = step.timestamp != INVALID_TIMESTAMP;
	const double t = timed ? toSeconds(step.timestamp) : r.lastT;
	const double dt = r.anyTimed ? t - r.lastT : 0;
	if (timed && !r.anyTimed) r.firstT = t;
	if (timed && r.anyTimed) r.longestGap = std::max(r.longestGap, dt);
	r.anyTimed = r.anyTimed || timed;
	r.lastT = t;
	const se2::Pose est = r.filter.meanPose();
	const auto n = summary.steps;
	const auto& fr = r.filter.lastFrame();
	const bool updated = fr.timestamp == step.timestamp && r.filter.stats().frames > 0;
	const se2::Pose smoothed = r.controllerPose.update(
		stepIncrement, dt, est, updated && (fr.kidnapDeclared || fr.kidnapReverted || fr.poseFound));
	if (summary.startPose) noteStartPose(r, t, updated && fr.poseFound, *summary.startPose);
	if (r.filter.poseKnown())
	{
		r.outputs.rbpf.write(n, t, est);
		r.outputs.tum.write(n, t, est);
		r.outputs.smoothed.write(n, t, smoothed);
		r.estimated.push_back({t, est, static_cast<long>(n)});
	}
	else
		for (auto* path : {&r.outputs.rbpf, &r.outputs.tum, &r.outputs.smoothed}) path->writeUnknown(n, t);
	r.outputs.odometry.write(n, t, r.odo);
	r.outputs.odometryTum.write(n, t, r.odo);
	r.odometry.push_back({t, r.odo, static_cast<long>(n)});
	// The particle cloud's spread: weighted standard deviation of the
	// position (sqrt of the covariance's trace) and of the heading.
	const Eigen::Matrix3d cov = r.filter.poseCovariance();
	r.outputs.stepLog.print("%llu %.6f %.4f %.3f %zu %.4f %zu %d %zu %zu %.4f %.4f %.3f\n",
		static_cast<unsigned long long>(n), t, r.filter.ESS(), updated ? fr.dualRatio : 0.0,
		updated ? fr.dualParticles : size_t(0), updated ? fr.explainedFraction : 0.0,
		updated ? fr.hypothesisSupport : size_t(0), !updated ? 0 : fr.kidnapDeclared ? 1 : fr.kidnapReverted ? -1 : 0,
		r.filter.landmarkIndex().size(), updated ? fr.used : size_t(0), ms,
		std::sqrt(std::max(0.0, cov(0, 0) + cov(1, 1))), std::sqrt(std::max(0.0, cov(2, 2))) * 180 / M_PI);
	r.outputs.stepLog.flush();
}

void CVSlamApp::noteStartPose(const RunState& r, double t, bool foundNow, RunSummary::StartPose& start) const
{
	const double sinceStart = t - r.firstT;
	if (!start.firstMappedSightingAt && r.filter.stats().measurementsWhilePoseUnknown > 0)
		start.firstMappedSightingAt = sinceStart;
	if (foundNow) start.foundAt = sinceStart;
	if (!r.filter.poseKnown()) start.unknownSteps++;
}

void CVSlamApp::summarizeReader(const CRawlogReader& reader, const RunState& r, RunSummary& summary) const
{
	summary.stepMeanMs = summary.steps ? r.stepSumMs / summary.steps : 0;
	summary.realTimeSpan = r.lastT - r.firstT;
	summary.longestGap = r.longestGap;
	summary.actionFrameSteps = reader.actionFrameSteps();
	summary.observationSteps = reader.observationSteps();
	summary.skippedObjects = reader.skippedObjects();
	if (!r.frontEnd) return;
	const CVisualFrontEnd& fe = *r.frontEnd;
	RunSummary::FrontEnd e = r.frontEndSummary;
	const auto& t = fe.totalSeconds();
	e.featuresSeconds = t.features;
	e.searchSeconds = t.search;
	e.poseSeconds = t.pose;
	e.creationSeconds = t.creation;
	e.headingSeconds = t.heading;
	e.headingChanges = fe.headingChangesMeasured();
	e.headingChangesFailed = fe.headingChangesFailed();
	const auto& db = fe.database();
	e.landmarks = db.size();
	e.bytesPerLandmark = db.size() ? double(db.landmarkBytes()) / db.size() : 0.0;
	e.indexBytes = static_cast<double>(db.indexBytes());
	e.creationAttempts = fe.creationAttempts();
	e.creationRejections = fe.creationRejections();
	e.poorlyConditioned = fe.poorlyConditionedRecognitions();
	e.inconsistent = fe.inconsistentRecognitions();
	summary.frontEnd = e;
}

void CVSlamApp::writeFinalOutputs(
	const RunOutputFolder& folder, const RunState& r, const Trajectory& groundTruth, RunSummary& summary) const
{
	// Also after an error or an interruption: what the run got to.
	const auto& best = r.filter.particle(r.filter.bestParticleIndex());
	std::vector<uint64_t> measurements;
	const LandmarkMap map = landmarkMapOf(r.filter.landmarkIndex(), best.bank, &measurements);
	writeLandmarkMap(folder.file("final_map.txt"), map, measurements, summary.runId);
	writeVSlamMap(folder.file("final_map.vslam"), mapOfRun(r.filter, r.frontEnd.get(), summary.runId));
	Trajectory smoothed;  // the best particle's path
	{
		COutputFile f(folder.file("most_likely_path.txt"), COutputFile::Mode::Atomic);
		const double found = summary.startPose && summary.startPose->foundAt ? r.firstT + *summary.startPose->foundAt : -1e300;
		for (const auto& e : best.path.toVector())
		{
			if (!r.filter.poseKnown() || toSeconds(e.t) < found) continue;  // before the pose was found
			smoothed.push_back({toSeconds(e.t), e.pose});
			f.print("%.3f %.3f %.3f\n", e.pose.x, e.pose.y, e.pose.phi);
		}
		f.commit();
		writeTumTrajectory(folder.file("most_likely_path.tum"), smoothed, summary.runId);
	}
	Trajectory poseGraphPath;  // the loop-closure graph's solution at the end
	if (const CLandmarkPoseGraph* graph = r.filter.loopClosureGraph(); graph && graph->keyframes() > 0)
	{
		CLandmarkPoseGraph solved = *graph;
		solved.optimize();
		Trajectory keyframes;
		for (const auto& [t, pose] : solved.keyframePath()) keyframes.push_back({toSeconds(t), pose});
		poseGraphPath = keyframesAlongOdometry(keyframes, r.odometry);
		writeTumTrajectory(folder.file("pose_graph_path.tum"), poseGraphPath, summary.runId);
		std::ostringstream text;  // for graph-slam --view -i
		solved.toMrptGraph().writeAsText(text);
		COutputFile g(folder.file("pose_graph.graph"), COutputFile::Mode::Atomic);
		g.write(text.str());
		g.commit();
	}
	writeRunScene(folder.file("final_map.3Dscene"),
		sceneOf(r.estimated, r.odometry, groundTruth, r.filter.landmarkIndex(), best.bank, m_rawlogFile));
	if (groundTruth.empty()) return;
	summary.ate = computeAte(r.estimated, groundTruth);
	summary.ateAligned = computeAte(r.estimated, groundTruth, {0.5, true});
	summary.odometryAte = computeAte(r.odometry, groundTruth);
	if (!smoothed.empty())
	{
		summary.smoothedAte = computeAte(smoothed, groundTruth);
		summary.smoothedAteAligned = computeAte(smoothed, groundTruth, {0.5, true});
	}
	if (!poseGraphPath.empty()) summary.poseGraphAte = computeAte(poseGraphPath, groundTruth);
	checkGroundTruthBelongsToTheRun(r, groundTruth, summary);
}

void CVSlamApp::checkGroundTruthBelongsToTheRun(const RunState& r, const Trajectory& groundTruth, RunSummary& summary) const
{
	if (r.estimated.empty()) return;
	summary.groundTruthCover = groundTruthCover(r.estimated, groundTruth);
	const std::string gt = "[vslam] ground_truth_file '" + m_groundTruthFile + "'";
	if (summary.groundTruthCover == 0)
		throw ConfigError(gt + " has no pose at any step's time of rawlog '" + m_rawlogFile + "' (it spans " +
			std::to_string(groundTruth.front().t) + " to " + std::to_string(groundTruth.back().t) + " s, the run " +
			std::to_string(r.estimated.front().t) + " to " + std::to_string(r.estimated.back().t) +
			" s): it is not this rawlog's ground truth");
	char share[64];
	if (summary.groundTruthCover < 0.95)
	{
		std::snprintf(share, sizeof share, "%.1f%%", 100 * summary.groundTruthCover);
		summary.groundTruthWarning = gt + " covers only " + share + " of the steps; the error figures are over those";
	}
	const double disagreement = odometryDisagreement(r.odometry, groundTruth);
	if (disagreement > 0.2)
	{
		std::snprintf(share, sizeof share, "%.0f%%", 100 * disagreement);
		summary.groundTruthWarning += std::string(summary.groundTruthWarning.empty() ? "" : "; ") +
			"the odometry disagrees with " + gt + " in " + share +
			" of the seconds the robot moved: is it this rawlog's ground truth?";
	}
}

int CVSlamApp::main(int argc, const char** argv)
{
	keepImageBuffersInTheProcess();
	useOnlyAllottedCpus();
	try
	{
		if (!initialize(argc, argv)) return kOk;
		return run();
	}
	catch (const std::invalid_argument& e)
	{
		std::cerr << "vslam: error: " << e.what() << "\n\n" << usage();
		return kUsage;
	}
	catch (const ConfigError& e)
	{
		std::cerr << "vslam: error: " << e.what() << "\n";
		return kConfigError;
	}
	catch (const InputError& e)
	{
		std::cerr << "vslam: error: " << e.what() << "\n";
		return kInputError;
	}
	catch (const std::bad_alloc&)
	{
		std::cerr << "vslam: error: out of memory (a smaller [vslam_particle_filter] sampleSize may fit)\n";
		return kOtherError;
	}
	catch (const std::exception& e)
	{
		std::cerr << "vslam: error: " << exceptionText(e) << "\n";
		return kOtherError;
	}
}

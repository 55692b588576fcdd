#include <libvslam/app/CVSlamApp.h>
#include <libvslam/app/InterruptFlag.h>
#include <libvslam/config/ConfigError.h>
#include <libvslam/config/ConfigReference.h>
#include <libvslam/config/IniText.h>
#include <libvslam/config/KeyValidation.h>
#include <libvslam/config/Overrides.h>
#include <libvslam/core/ActionOdometry.h>
#include <libvslam/core/InputError.h>
#include <libvslam/eval/Trajectory.h>
#include <libvslam/filter/CVSlamParticleFilter.h>
#include <libvslam/frontend/ImageBufferAllocation.h>
#include <libvslam/frontend/ImagesToMeasurements.h>
#include <libvslam/io/CPathFileWriter.h>
#include <libvslam/io/CRawlogReader.h>
#include <libvslam/io/ExceptionText.h>
#include <libvslam/io/LandmarkMapFile.h>
#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/system/datetime.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
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
	TVSlamAppOptions().saveToConfigFile(c, TVSlamAppOptions::kSection);
	TVSlamFilterOptions().saveToConfig(c);
	TVisualFrontEndOptions().saveToConfigFile(c, TVisualFrontEndOptions::kSection);
	std::string text;
	c.getContent(text);
	return text;
}

config::KnownKeys CVSlamApp::knownKeys()
{
	config::KnownKeys known;
	known.addFromOptions(TVSlamAppOptions(), TVSlamAppOptions::kSection);
	TVSlamFilterOptions().registerKnownKeys(known);
	known.addFromOptions(TVisualFrontEndOptions(), TVisualFrontEndOptions::kSection);
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
	std::ifstream in(file);
	if (!in) throw ConfigError("cannot read configuration file '" + file + "'");
	std::stringstream text;
	text << in.rdbuf();
	std::vector<config::Override> parsed;
	for (const auto& o : overrides) parsed.push_back(config::parseOverride(o));
	params = config::parseIniWithOverrides(text.str(), parsed);

	config::checkNoUnknownKeys(params, knownKeys());
	appOptions.loadFromConfigFile(params, TVSlamAppOptions::kSection);
	filterOptions.loadFromConfig(params);
	frontEndOptions.loadFromConfigFile(params, TVisualFrontEndOptions::kSection);
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
			std::cout << (markdown ? config::markdownReference(defaultConfigText()) : defaultConfigText());
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
}  // namespace

int CVSlamApp::run()
{
	// Validate inputs before touching the output folder: a bad rawlog or
	// ground-truth file leaves earlier outputs intact.
	CRawlogReader reader(m_rawlogFile);
	Trajectory groundTruth;
	if (!m_groundTruthFile.empty()) groundTruth = readTrajectory(m_groundTruthFile);
	LandmarkMap priorMap;
	if (!m_priorMapFile.empty())
		priorMap = readLandmarkMap(
			m_priorMapFile, appOptions.prior_map_std_xy, appOptions.prior_map_std_phi);

	std::error_code ec;
	fs::create_directories(m_outputDir, ec);
	if (!fs::is_directory(m_outputDir))
		throw InputError("cannot create output folder '" + m_outputDir + "'");
	const auto out = [&](const char* name) { return (fs::path(m_outputDir) / name).string(); };

	RunSummary summary;
	summary.configFile = m_configFile;
	summary.rawlogFile = m_rawlogFile;
	summary.outputDir = m_outputDir;
	summary.seed = appOptions.RANDOM_SEED >= 0
		? static_cast<uint64_t>(appOptions.RANDOM_SEED)
		: static_cast<uint32_t>(
			  std::chrono::system_clock::now().time_since_epoch().count());
	// Seed once, before any draw: MRPT 2.5 does not restart its cached
	// Gaussian on a reseed, so a later reseed would not repeat a run.
	mrpt::random::getRandomGenerator().randomize(static_cast<uint32_t>(summary.seed));
	{
		std::ofstream cfg(out("config_used.ini"));
		std::string text;
		params.getContent(text);
		cfg << "; effective configuration of this run (INI + overrides)\n"
			<< "; random seed used: " << summary.seed << "\n"
			<< text;
	}

	// The first step is read before the filter exists: it may set the start.
	RawlogStep step;
	bool haveStep = reader.next(step);
	if (appOptions.initial_pose_from_ground_truth)
	{
		if (groundTruth.empty())
			throw ConfigError("configuration '" + m_configFile +
				"': initial_pose_from_ground_truth needs [vslam] ground_truth_file");
		const double t0 = haveStep ? toSeconds(step.timestamp) : groundTruth.front().t;
		const auto p = interpolate(groundTruth, std::max(t0, groundTruth.front().t), 1e9);
		filterOptions.pf.initialPose = p ? *p : groundTruth.front().pose;
		// That is the pose at the first step's time, i.e. after the first
		// step's odometry increment (which leads up to it): not applied again.
		step.action.reset();
	}
	CVSlamParticleFilter filter(filterOptions);
	if (!priorMap.empty()) filter.setPriorMap(priorMap);
	mrpt::bayes::CParticleFilter pf;
	pf.m_options = filterOptions.pf.toMrpt();
	CPathFileWriter pathRbpf(out("log_estimated_path.txt"), CPathFileWriter::Format::RbpfSlam);
	CPathFileWriter pathTum(out("estimated_path.tum"), CPathFileWriter::Format::Tum);
	CPathFileWriter pathOdo(out("log_odometry_path.txt"), CPathFileWriter::Format::RbpfSlamOdometry);
	CPathFileWriter pathOdoTum(out("odometry_path.tum"), CPathFileWriter::Format::Tum);
	CPathFileWriter pathSmoothed(out("smoothed_path.tum"), CPathFileWriter::Format::Tum);
	CSmoothedPose controllerPose(filterOptions.smoothedPose);  // smoothed_path.tum
	FILE* stepLog = std::fopen(out("log_filter_steps.txt").c_str(), "wt");
	if (!stepLog) throw InputError("cannot create output file '" + out("log_filter_steps.txt") + "'");
	std::fprintf(stepLog,
		"%% step timestamp ESS dual_ratio dual_particles explained_fraction "
		"hypothesis_support kidnap_declared landmarks measurements_used step_ms spread_xy spread_phi_deg\n");

	ProgressReporter progress(appOptions.show_progress);
	InterruptFlag interrupt;
	Trajectory estimated, odometry;
	se2::Pose odo = filterOptions.pf.initialPose;
	std::unique_ptr<CVisualFrontEnd> frontEnd;
	RunSummary::FrontEnd frontEndSummary;
	double firstT = 0, lastT = 0, stepSumMs = 0;
	bool anyTimed = false;
	const auto start = std::chrono::steady_clock::now();
	std::string failure;
	int exitCode = kOk;
	try
	{
		for (; haveStep; haveStep = reader.next(step))
		{
			if (interrupt.raised())
			{
				summary.status = "interrupted";
				exitCode = kInterrupted;
				break;
			}
			const auto t0 = std::chrono::steady_clock::now();
			se2::Pose stepIncrement{0, 0, 0};
			if (step.action)
				if (const auto u = odometryIncrement(*step.action))
					stepIncrement = u->asTPose(), odo = se2::compose(odo, stepIncrement);
			if (hasImages(*step.sf))
			{
				// Camera images: the front-end turns them into measurements.
				if (!frontEnd) frontEnd = std::make_unique<CVisualFrontEnd>(frontEndOptions);
				const auto r = replaceImagesWithMeasurements(*frontEnd, *step.sf,
					mrpt::poses::CPose2D(odo.x, odo.y, odo.phi),
					"rawlog '" + m_rawlogFile + "', entry " + std::to_string(step.entry));
				frontEndSummary.images += r.images;
				frontEndSummary.measurements += r.measurements;
				frontEndSummary.created += r.created;
				frontEndSummary.pruned += r.pruned;
			}
			try
			{
				pf.executeOn(filter, step.action.get(), step.sf.get());
			}
			catch (const std::exception& e)
			{
				// Bad data found by the filter arrives wrapped by MRPT.
				const std::string why = filter.takeInputError();
				if (why.empty()) throw;
				throw InputError("rawlog '" + m_rawlogFile + "', entry " + std::to_string(step.entry) + ": " + why);
			}
			const double ms = std::chrono::duration<double, std::milli>(
								  std::chrono::steady_clock::now() - t0).count();
			stepSumMs += ms;
			summary.stepMaxMs = std::max(summary.stepMaxMs, ms);

			// A step without a timestamp (e.g. an empty last frame) keeps the
			// previous step's, so the TUM output stays ordered.
			const bool timed = step.timestamp != INVALID_TIMESTAMP;
			const double t = timed ? toSeconds(step.timestamp) : lastT;
			const double dt = anyTimed ? t - lastT : 0;
			if (timed && !anyTimed) firstT = t;
			anyTimed = anyTimed || timed;
			lastT = t;
			const se2::Pose est = filter.meanPose();
			pathRbpf.write(summary.steps, t, est);
			pathTum.write(summary.steps, t, est);
			pathOdo.write(summary.steps, t, odo);
			pathOdoTum.write(summary.steps, t, odo);
			const long stepIndex = static_cast<long>(summary.steps);
			estimated.push_back({t, est, stepIndex});
			odometry.push_back({t, odo, stepIndex});
			const auto& fr = filter.lastFrame();
			const bool updated = fr.timestamp == step.timestamp && filter.stats().frames > 0;
			pathSmoothed.write(summary.steps, t,
				controllerPose.update(stepIncrement, dt, est, updated && (fr.kidnapDeclared || fr.kidnapReverted)));
			// The particle cloud's spread: weighted standard deviation of the
			// position (sqrt of the covariance's trace) and of the heading.
			const Eigen::Matrix3d cov = filter.poseCovariance();
			std::fprintf(stepLog, "%llu %.6f %.4f %.3f %zu %.4f %zu %d %zu %zu %.4f %.4f %.3f\n",
				static_cast<unsigned long long>(summary.steps), t, filter.ESS(),
				updated ? fr.dualRatio : 0.0, updated ? fr.dualParticles : size_t(0),
				updated ? fr.explainedFraction : 0.0, updated ? fr.hypothesisSupport : size_t(0),
				!updated ? 0 : fr.kidnapDeclared ? 1 : fr.kidnapReverted ? -1 : 0, filter.landmarkIndex().size(),
				updated ? fr.used : size_t(0), ms, std::sqrt(std::max(0.0, cov(0, 0) + cov(1, 1))),
				std::sqrt(std::max(0.0, cov(2, 2))) * 180 / M_PI);
			std::fflush(stepLog);
			summary.steps++;
			progress.update(reader.progress(), summary.steps, filter.landmarkIndex().size(),
				filter.ESS());
			if (appOptions.max_steps > 0 && summary.steps >= appOptions.max_steps) break;
		}
	}
	catch (const InputError& e)
	{
		summary.status = "failed";
		summary.error = failure = e.what();
	}
	progress.finish();
	std::fclose(stepLog);

	summary.totalSeconds =
		std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	summary.stepMeanMs = summary.steps ? stepSumMs / summary.steps : 0;
	summary.realTimeSpan = lastT - firstT;
	summary.actionFrameSteps = reader.actionFrameSteps();
	summary.observationSteps = reader.observationSteps();
	summary.skippedObjects = reader.skippedObjects();
	if (frontEnd)
	{
		const auto& t = frontEnd->totalSeconds();
		frontEndSummary.featuresSeconds = t.features;
		frontEndSummary.searchSeconds = t.search;
		frontEndSummary.poseSeconds = t.pose;
		frontEndSummary.creationSeconds = t.creation;
		frontEndSummary.headingSeconds = t.heading;
		frontEndSummary.headingChanges = frontEnd->headingChangesMeasured();
		frontEndSummary.headingChangesFailed = frontEnd->headingChangesFailed();
		const auto& db = frontEnd->database();
		frontEndSummary.landmarks = db.size();
		frontEndSummary.bytesPerLandmark = db.size() ? double(db.landmarkBytes()) / db.size() : 0.0;
		frontEndSummary.indexBytes = static_cast<double>(db.indexBytes());
		frontEndSummary.creationAttempts = frontEnd->creationAttempts();
		frontEndSummary.creationRejections = frontEnd->creationRejections();
		frontEndSummary.poorlyConditioned = frontEnd->poorlyConditionedRecognitions();
		frontEndSummary.ambiguous = frontEnd->ambiguousRecognitions();
		frontEndSummary.narrow = frontEnd->narrowRecognitions();
		frontEndSummary.inconsistent = frontEnd->inconsistentRecognitions();
		summary.frontEnd = frontEndSummary;
	}

	// Final outputs: also after an error or an interruption.
	const auto& best = filter.particle(filter.bestParticleIndex());
	writeLandmarkMap(out("final_map.txt"), filter.landmarkIndex(), best.bank);
	Trajectory smoothed;  // the best particle's path
	{
		FILE* f = std::fopen(out("most_likely_path.txt").c_str(), "wt");
		for (const auto& e : best.path.toVector())
		{
			smoothed.push_back({toSeconds(e.t), e.pose});
			if (f) std::fprintf(f, "%.3f %.3f %.3f\n", e.pose.x, e.pose.y, e.pose.phi);
		}
		if (f) std::fclose(f);
		writeTumTrajectory(out("most_likely_path.tum"), smoothed);
	}
	Trajectory poseGraphPath;  // the loop-closure graph's solution at the end
	if (const CLandmarkPoseGraph* graph = filter.loopClosureGraph(); graph && graph->keyframes() > 0)
	{
		CLandmarkPoseGraph solved = *graph;
		solved.optimize();
		for (const auto& [t, pose] : solved.keyframePath()) poseGraphPath.push_back({toSeconds(t), pose});
		writeTumTrajectory(out("pose_graph_path.tum"), poseGraphPath);
	}
	if (!groundTruth.empty())
	{
		summary.ate = computeAte(estimated, groundTruth);
		summary.ateAligned = computeAte(estimated, groundTruth, {0.5, true});
		summary.odometryAte = computeAte(odometry, groundTruth);
		if (!smoothed.empty())
		{
			summary.smoothedAte = computeAte(smoothed, groundTruth);
			summary.smoothedAteAligned = computeAte(smoothed, groundTruth, {0.5, true});
		}
		if (!poseGraphPath.empty()) summary.poseGraphAte = computeAte(poseGraphPath, groundTruth);
	}
	summary.peakMemoryMiB = peakMemoryMiB();
	summary.write(out("run_summary.yaml"), filter);
	std::cerr << summary.brief(filter);
	std::cerr << "vslam: outputs in " << m_outputDir << "/\n";
	if (!failure.empty()) throw InputError(failure);
	return exitCode;
}

int CVSlamApp::main(int argc, const char** argv)
{
	keepImageBuffersInTheProcess();
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
	catch (const std::exception& e)
	{
		std::cerr << "vslam: error: " << exceptionText(e) << "\n";
		return kOtherError;
	}
}

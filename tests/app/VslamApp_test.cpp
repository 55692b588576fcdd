/** The vslam app as users run it: the built binary on real files, checked
 * by exit code, message and output files. */
#include <gtest/gtest.h>
#include <libvslam/app/RunSummary.h>
#include <libvslam/core/ActionOdometry.h>
#include <libvslam/eval/AbsoluteTrajectoryError.h>
#include <libvslam/io/CRawlogReader.h>
#include <libvslam/io/LandmarkMapFile.h>
#include <libvslam/obs/registerClasses.h>
#include <libvslam/world/FloorPlanFile.h>
#include <mrpt/graphs/CNetworkOfPoses.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <tests/support/RunCommand.h>
#include <tests/support/TempDir.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace vslam;
using vslam::testing::readFile;
using vslam::testing::contains;
using vslam::testing::lineCount;
using vslam::testing::quoted;
using vslam::testing::runCommand;
using vslam::testing::TempDir;
namespace fs = std::filesystem;

namespace
{
// Reading the demo rawlog in-process needs vslam's observation classes.
const bool kRegistered = (vslam::registerObservationClasses(), true);
const std::string kSource = VSLAM_SOURCE_DIR;
const std::string kVslam = std::string(VSLAM_BINARY_DIR) + "/bin/vslam";
const std::string kDemoIni = kSource + "/config_ini/demo_visual.ini";
const std::string kDemoRawlog = kSource + "/rawlogs/demo_visual.rawlog";
const std::string kDemoTruth = kSource + "/rawlogs/demo_visual_groundtruth.tum";

/** vslam with the demo INI and the given arguments. */
vslam::testing::CommandResult runDemo(const std::string& args)
{
	return runCommand(quoted(kVslam) + " " + quoted(kDemoIni) + " --quiet " + args);
}


/** A copy of the demo rawlog cut to `fraction` of its bytes. */
std::string truncatedDemo(const TempDir& dir, double fraction)
{
	const std::string bytes = readFile(kDemoRawlog);
	const std::string file = dir.file("truncated.rawlog");
	std::ofstream(file, std::ios::binary) << bytes.substr(0, size_t(bytes.size() * fraction));
	return file;
}

/** The RMSE of one path in run_summary.yaml ("vslam", "dead_reckoning"). */
double summaryRmse(const std::string& summaryFile, const std::string& name)
{
	return summaryNumber(readRunSummary(summaryFile), "error_vs_ground_truth_m." + name + ".rmse");
}
}  // namespace

// --------------------------------------------------------------------------
// Main job and outputs
// --------------------------------------------------------------------------
TEST(VslamApp, DemoRunWritesEveryOutputAndBeatsDeadReckoning)
{
	TempDir dir;
	const auto r = runDemo("--out " + quoted(dir.file("out")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	for (const char* f : {"log_estimated_path.txt", "estimated_path.tum", "log_odometry_path.txt",
			 "log_filter_steps.txt", "final_map.txt", "most_likely_path.txt",
			 "most_likely_path.tum", "pose_graph_path.tum", "run_summary.yaml", "config_used.ini", "final_map.3Dscene",
			 "pose_graph.graph"})
		EXPECT_TRUE(fs::exists(dir.file("out/") + f)) << f;
	// rbpf-slam's format: one row per step, 8 columns.
	const Trajectory est = readRbpfSlamPath(dir.file("out/log_estimated_path.txt"));
	EXPECT_EQ(est.size(), 3000u);
	EXPECT_EQ(est.back().step, 2999);
	EXPECT_EQ(readTrajectory(dir.file("out/estimated_path.tum")).size(), 3000u);
	// Accuracy, recomputed from the outputs (not from the summary).
	const AteStats ate = computeAte(est, readTrajectory(kDemoTruth));
	EXPECT_EQ(ate.associated, 3000u);
	EXPECT_NEAR(summaryRmse(dir.file("out/run_summary.yaml"), "vslam"), ate.rmse, 1e-3);
	// The best particle's path at the end: one pose per camera frame, its
	// error in the summary as recomputed here, raw and aligned.
	const Trajectory smoothed = readTrajectory(dir.file("out/most_likely_path.tum"));
	ASSERT_GT(smoothed.size(), 100u);
	const AteStats smoothedAte = computeAte(smoothed, readTrajectory(kDemoTruth));
	EXPECT_EQ(smoothedAte.associated, smoothed.size());
	EXPECT_NEAR(summaryRmse(dir.file("out/run_summary.yaml"), "most_likely_path"), smoothedAte.rmse, 1e-3);
	TAteOptions aligned;
	aligned.align = true;
	const double smoothedAligned = computeAte(smoothed, readTrajectory(kDemoTruth), aligned).rmse;
	EXPECT_NEAR(summaryRmse(dir.file("out/run_summary.yaml"), "most_likely_path_se2_aligned"), smoothedAligned, 1e-3);
	EXPECT_LE(smoothedAligned, smoothedAte.rmse + 1e-9);
	// The loop-closure graph's path at the end: one pose per keyframe (a
	// frame that measured a visual landmark), its error in the summary.
	// Measured: 0.62 m RMSE (0.08 m median, the kidnap included).
	const Trajectory graphPath = readTrajectory(dir.file("out/pose_graph_path.tum"));
	ASSERT_GT(graphPath.size(), 100u);
	const AteStats graphAte = computeAte(graphPath, readTrajectory(kDemoTruth));
	EXPECT_NEAR(summaryRmse(dir.file("out/run_summary.yaml"), "pose_graph_path"), graphAte.rmse, 1e-3);
	EXPECT_LT(graphAte.rmse, 0.5 * summaryRmse(dir.file("out/run_summary.yaml"), "dead_reckoning"));
	// Measured: 0.68 m RMSE (0.16 m median, the kidnap included), dead
	// reckoning 2.58 m.
	EXPECT_LT(ate.rmse, 0.5 * summaryRmse(dir.file("out/run_summary.yaml"), "dead_reckoning"));
	EXPECT_LT(ate.median, 0.3);
	EXPECT_EQ(lineCount(dir.file("out/log_odometry_path.txt")), 3000u);
	const std::string summary = readFile(dir.file("out/run_summary.yaml"));
	EXPECT_TRUE(contains(summary, "status: completed")) << summary;
	EXPECT_TRUE(contains(summary, "kidnaps_detected: 1")) << summary;  // the demo's kidnap
	EXPECT_TRUE(contains(summary, "kidnaps_reverted: 0")) << summary;  // a real one: it stands
	EXPECT_TRUE(contains(summary, "peak_memory_MiB: ")) << summary;
}

TEST(VslamApp, SameSeedSameOutputsByteForByte)
{
	TempDir dir;
	ASSERT_EQ(runDemo("--out " + quoted(dir.file("a"))).exitCode, 0);
	ASSERT_EQ(runDemo("--out " + quoted(dir.file("b"))).exitCode, 0);
	ASSERT_EQ(runDemo("--out " + quoted(dir.file("c")) + " --set vslam.RANDOM_SEED=2").exitCode, 0);
	for (const char* f : {"log_estimated_path.txt", "estimated_path.tum", "final_map.txt",
			 "most_likely_path.txt", "log_odometry_path.txt"})
		EXPECT_EQ(readFile(dir.file("a/") + f), readFile(dir.file("b/") + f)) << f;
	EXPECT_NE(readFile(dir.file("a/log_estimated_path.txt")),
		readFile(dir.file("c/log_estimated_path.txt")));
}

TEST(VslamApp, SetOverridesAnyKeyAndRawlogArgumentOverridesTheIni)
{
	TempDir dir;
	const auto r = runDemo(quoted(kDemoRawlog) + " --out " + quoted(dir.file("o")) +
		" --set vslam_particle_filter.sampleSize=50 --set vslam.max_steps=100");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_TRUE(contains(readFile(dir.file("o/run_summary.yaml")), "particles: 50"));
	EXPECT_EQ(lineCount(dir.file("o/log_estimated_path.txt")), 100u);
	EXPECT_TRUE(contains(readFile(dir.file("o/config_used.ini")), "sampleSize"));
}

TEST(VslamApp, ObservationFormatRawlogsWork)
{
	// The demo rawlog rewritten in MRPT's observations-only format:
	// absolute odometry readings (CObservationOdometry) and measurements.
	TempDir dir;
	const std::string file = dir.file("obs.rawlog");
	{
		CRawlogReader in(kDemoRawlog);
		mrpt::io::CFileGZOutputStream out(file);
		auto arch = mrpt::serialization::archiveFrom(out);
		mrpt::poses::CPose2D odo(0, 0, 0);
		RawlogStep s;
		while (in.next(s))
		{
			auto o = mrpt::obs::CObservationOdometry::Create();
			if (s.action)
				if (const auto u = odometryIncrement(*s.action)) odo = odo + *u;
			o->odometry = odo;
			o->timestamp = s.action->getActionByClass<mrpt::obs::CActionRobotMovement2D>()->timestamp;
			arch << *o;
			for (const auto& obs : *s.sf) arch << *obs;
		}
	}
	const auto r = runDemo(quoted(file) + " --out " + quoted(dir.file("o")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const std::string summary = readFile(dir.file("o/run_summary.yaml"));
	EXPECT_TRUE(contains(summary, "action_sensoryframe_steps: 0")) << summary;
	const double rmse = summaryRmse(dir.file("o/run_summary.yaml"), "vslam");
	const double odo = summaryRmse(dir.file("o/run_summary.yaml"), "dead_reckoning");
	EXPECT_LT(rmse, 0.5 * odo) << summary;
}

TEST(VslamApp, RunsMrptsKfSlamDemo)
{
	const std::string ini = kSource + "/config_ini/kfslam_demo_range_bearing.ini";
	if (!fs::exists("/usr/share/mrpt/datasets/kf-slam_demo.rawlog"))
		GTEST_SKIP() << "MRPT's kf-slam demo rawlog is absent (package mrpt-common)";
	TempDir dir;
	const auto r = runCommand(quoted(kVslam) + " " + quoted(ini) + " --quiet --out " + quoted(dir.file("o")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	// Matched by step with MRPT's ground-truth pose list. Measured: 6 mm
	// (dead reckoning 0.68 m).
	const double rmse = summaryRmse(dir.file("o/run_summary.yaml"), "vslam");
	EXPECT_LT(rmse, 0.05);
	EXPECT_LT(rmse, 0.1 * summaryRmse(dir.file("o/run_summary.yaml"), "dead_reckoning"));
}

TEST(VslamApp, LocalizesInAPriorMapFromAWrongStart)
{
	// A simulated range-bearing run and its true beacon map; the filter
	// starts at (0, 0, 0), metres away from the true start: the known
	// beacons must relocalize it (a kidnap at the start), and no new
	// landmark may appear.
	TempDir dir;
	const std::string sim = std::string(VSLAM_BINARY_DIR) + "/bin/vslam-simul-measurements";
	ASSERT_EQ(runCommand(quoted(sim) + " " + quoted(kSource + "/config_ini/simul_range_bearing.ini") + " " +
				  quoted(dir.file("rb.rawlog")) + " --set vslam_sim.duration=120")
				  .exitCode,
		0);
	const auto r = runCommand(quoted(kVslam) + " " +
		quoted(kSource + "/config_ini/kfslam_demo_range_bearing.ini") + " " + quoted(dir.file("rb.rawlog")) +
		" --quiet --out " + quoted(dir.file("o")) + " --set vslam.ground_truth_file=" +
		quoted(dir.file("rb_groundtruth.tum")) + " --set vslam.prior_map_file=" +
		quoted(dir.file("rb_landmarks.txt")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const std::string summary = readFile(dir.file("o/run_summary.yaml"));
	const auto parsed = readRunSummary(dir.file("o/run_summary.yaml"));
	EXPECT_EQ(summaryNumber(parsed, "landmarks.total"), 20) << summary;
	EXPECT_EQ(summaryNumber(parsed, "landmarks.point"), 20) << summary;
	EXPECT_TRUE(contains(summary, "created_at_first_sighting: 0")) << summary;
	EXPECT_FALSE(contains(summary, "kidnaps_detected: 0")) << summary;
	const Trajectory est = readRbpfSlamPath(dir.file("o/log_estimated_path.txt"));
	const Trajectory truth = readTrajectory(dir.file("rb_groundtruth.tum"));
	EXPECT_GT(computeAte(Trajectory(est.begin(), est.begin() + 5), truth).median, 1.0);
	const Trajectory late(est.begin() + 300, est.end());  // after 30 s
	EXPECT_LT(computeAte(late, truth).median, 0.2);

	const auto bad = runDemo("--out " + quoted(dir.file("x")) + " --set vslam.prior_map_file=" +
		quoted(dir.file("nomap.txt")));
	EXPECT_EQ(bad.exitCode, 3) << bad.output;
	EXPECT_TRUE(contains(bad.output, "nomap.txt")) << bad.output;
	EXPECT_FALSE(fs::exists(dir.file("x")));
}

// --------------------------------------------------------------------------
// Bad input: one clear message, non-zero exit, earlier outputs intact
// --------------------------------------------------------------------------
TEST(VslamApp, MissingRawlogIsNamedAndOutputsAreLeftAlone)
{
	TempDir dir;
	fs::create_directories(dir.file("o"));
	std::ofstream(dir.file("o/log_estimated_path.txt")) << "earlier run\n";
	const auto r = runDemo(quoted(dir.file("nope.rawlog")) + " --out " + quoted(dir.file("o")));
	EXPECT_EQ(r.exitCode, 3);
	EXPECT_TRUE(contains(r.output, dir.file("nope.rawlog"))) << r.output;
	EXPECT_EQ(readFile(dir.file("o/log_estimated_path.txt")), "earlier run\n");
}

TEST(VslamApp, TruncatedRawlogFailsNamingFileAndEntryAndKeepsOutputsSoFar)
{
	TempDir dir;
	const std::string file = truncatedDemo(dir, 0.5);
	const auto r = runDemo(quoted(file) + " --out " + quoted(dir.file("o")));
	EXPECT_EQ(r.exitCode, 3) << r.output;
	EXPECT_TRUE(contains(r.output, file)) << r.output;
	EXPECT_TRUE(contains(r.output, "entry")) << r.output;
	// What was processed before the damage is on disk, well-formed.
	const Trajectory est = readRbpfSlamPath(dir.file("o/log_estimated_path.txt"));
	EXPECT_GT(est.size(), 500u);
	EXPECT_LT(est.size(), 3000u);
	const std::string summary = readFile(dir.file("o/run_summary.yaml"));
	EXPECT_TRUE(contains(summary, "status: failed")) << summary;
	EXPECT_TRUE(contains(summary, "error: ")) << summary;
}

TEST(VslamApp, CorruptRawlogFailsNamingTheFile)
{
	TempDir dir;
	std::string bytes = readFile(kDemoRawlog);
	for (size_t i = bytes.size() / 3; i < bytes.size() / 3 + 64; i++) bytes[i] ^= 0x5a;
	const std::string file = dir.file("corrupt.rawlog");
	std::ofstream(file, std::ios::binary) << bytes;
	const auto r = runDemo(quoted(file) + " --out " + quoted(dir.file("o")));
	EXPECT_EQ(r.exitCode, 3) << r.output;
	EXPECT_TRUE(contains(r.output, file)) << r.output;

	std::ofstream(dir.file("text.rawlog")) << "this is not a rawlog\n";
	const auto t = runDemo(quoted(dir.file("text.rawlog")) + " --out " + quoted(dir.file("t")));
	EXPECT_EQ(t.exitCode, 3) << t.output;
	EXPECT_TRUE(contains(t.output, dir.file("text.rawlog"))) << t.output;
}

// Found by fuzz_rawlog: bytes on which MRPT 2.5.8's own deserializer
// dereferences a null pointer (entry 6). vslam used to die of SIGSEGV here.
TEST(VslamApp, RawlogThatCrashesMrptsDeserializerIsAnInputErrorNamingTheEntry)
{
	TempDir dir;
	const std::string file =
		std::string(VSLAM_SOURCE_DIR) + "/libvslam/io/testdata/segv_in_mrpt_deserializer_1.rawlog";
	const auto r = runDemo(quoted(file) + " --out " + quoted(dir.file("o")));
	EXPECT_EQ(r.exitCode, 3) << r.output;
	EXPECT_TRUE(contains(r.output, file + "', entry 6: corrupt data")) << r.output;
	EXPECT_TRUE(contains(readFile(dir.file("o/run_summary.yaml")), "status: failed"));
}

TEST(VslamApp, NanOdometryNamesTheEntry)
{
	TempDir dir;
	const std::string file = dir.file("nan.rawlog");
	{
		CRawlogReader in(kDemoRawlog);
		mrpt::io::CFileGZOutputStream out(file);
		auto arch = mrpt::serialization::archiveFrom(out);
		RawlogStep s;
		for (int i = 0; i < 200 && in.next(s); i++)
		{
			if (i == 150)
			{
				auto mv = s.action->getActionByClass<mrpt::obs::CActionRobotMovement2D>();
				const auto t = mv->timestamp;
				mv->computeFromOdometry(mrpt::poses::CPose2D(std::nan(""), 0, 0), {});
				mv->timestamp = t;
			}
			arch << *s.action << *s.sf;
		}
	}
	const auto r = runDemo(quoted(file) + " --out " + quoted(dir.file("o")));
	EXPECT_EQ(r.exitCode, 3) << r.output;
	EXPECT_TRUE(contains(r.output, "entry 300")) << r.output;  // 2 objects per step
	EXPECT_TRUE(contains(r.output, "not finite")) << r.output;
	EXPECT_EQ(lineCount(dir.file("o/log_estimated_path.txt")), 150u);
}

// Found by fuzz_rawlog: bad data the filter itself detects came out of
// MRPT's executeOn() wrapped in MRPT's exception type, so the run ended as
// "other error" (exit 4) without naming the entry or writing its summary.
TEST(VslamApp, BadMeasurementFoundByTheFilterIsAnInputErrorNamingTheEntry)
{
	TempDir dir;
	{
		mrpt::io::CFileGZOutputStream out(dir.file("rb.rawlog"));
		auto arch = mrpt::serialization::archiveFrom(out);
		for (int i = 0; i < 6; i++)
		{
			mrpt::obs::CActionCollection acts;
			mrpt::obs::CActionRobotMovement2D mv;
			mv.computeFromOdometry(mrpt::poses::CPose2D(0.1, 0, 0), {});
			mv.timestamp = mrpt::Clock::fromDouble(1.7e9 + i);
			acts.insert(mv);
			mrpt::obs::CSensoryFrame sf;
			auto br = mrpt::obs::CObservationBearingRange::Create();
			br->timestamp = mv.timestamp;
			br->sensorLabel = "RB";
			br->sensor_std_range = 0.05f;
			br->sensor_std_yaw = 0.02f;
			mrpt::obs::CObservationBearingRange::TMeasurement m;
			m.range = i == 4 ? 1e20f : 2.0f;
			m.yaw = 0.1f;
			m.pitch = 0;
			m.landmarkID = 3;
			br->sensedData.push_back(m);
			sf.insert(br);
			arch << acts << sf;
		}
	}
	std::ofstream(dir.file("rb.ini")) << "[vslam]\nrawlog_file = " << dir.file("rb.rawlog") << "\n";
	const auto r = runCommand(quoted(kVslam) + " " + quoted(dir.file("rb.ini")) + " --quiet --out " + quoted(dir.file("o")));
	EXPECT_EQ(r.exitCode, 3) << r.output;
	EXPECT_TRUE(contains(r.output, "entry 8")) << r.output;
	EXPECT_TRUE(contains(r.output, "beyond any sensor")) << r.output;
	const std::string summary = readFile(dir.file("o/run_summary.yaml"));
	EXPECT_TRUE(contains(summary, "status: failed")) << summary;
	EXPECT_EQ(lineCount(dir.file("o/log_estimated_path.txt")), 4u);
}

TEST(VslamApp, UnparsableValueNamesSectionAndKey)
{
	TempDir dir;
	const auto r = runDemo("--out " + quoted(dir.file("o")) + " --set vslam_particle_filter.sampleSize=lots");
	EXPECT_EQ(r.exitCode, 2) << r.output;
	EXPECT_TRUE(contains(r.output, "sampleSize")) << r.output;
	EXPECT_TRUE(contains(r.output, "vslam_particle_filter")) << r.output;
	EXPECT_TRUE(contains(r.output, "lots")) << r.output;
	EXPECT_FALSE(fs::exists(dir.file("o")));
}

TEST(VslamApp, OutOfRangeValueSaysTheAllowedRange)
{
	TempDir dir;
	const auto r = runDemo("--out " + quoted(dir.file("o")) + " --set vslam_particle_filter.BETA=1.5");
	EXPECT_EQ(r.exitCode, 2) << r.output;
	EXPECT_TRUE(contains(r.output, "BETA")) << r.output;
	EXPECT_TRUE(contains(r.output, "1.5")) << r.output;
	const auto n = runDemo("--out " + quoted(dir.file("o")) + " --set vslam_motion_model.sigma_T=-0.1");
	EXPECT_EQ(n.exitCode, 2) << n.output;
	EXPECT_TRUE(contains(n.output, "sigma_T")) << n.output;
}

TEST(VslamApp, MisspelledKeyIsAnErrorWithTheClosestKnownKey)
{
	TempDir dir;
	std::ofstream(dir.file("typo.ini")) << "[vslam]\nrawlog_file = " << kDemoRawlog
										<< "\n[vslam_motion_model]\nsigma_TT = 0.3\n";
	const auto r = runCommand(quoted(kVslam) + " " + quoted(dir.file("typo.ini")) + " --quiet --out " +
		quoted(dir.file("o")));
	EXPECT_EQ(r.exitCode, 2) << r.output;
	EXPECT_TRUE(contains(r.output, "sigma_TT")) << r.output;
	EXPECT_TRUE(contains(r.output, "did you mean 'sigma_T'")) << r.output;
	EXPECT_TRUE(contains(r.output, "typo.ini")) << r.output;
	// Sections of other programs in the same INI are not vslam's business.
	std::ofstream(dir.file("other.ini")) << "[vslam]\nrawlog_file = " << kDemoRawlog
										 << "\nmax_steps = 10\n[MappingApplication]\nanything = 1\n";
	EXPECT_EQ(runCommand(quoted(kVslam) + " " + quoted(dir.file("other.ini")) + " --quiet --out " +
				  quoted(dir.file("o2")))
				  .exitCode,
		0);
}

// Found by fuzz_config: MRPT's INI parser throws a plain runtime error for a
// broken directive; both apps report it as a configuration error naming the file.
TEST(VslamApp, BrokenIniSyntaxIsAConfigurationErrorNamingTheFile)
{
	TempDir dir;
	std::ofstream(dir.file("broken.ini")) << "[vslam]\nrawlog_file = " << kDemoRawlog
										  << "\nmax_steps = $eval{s =\n";
	const auto r = runCommand(quoted(kVslam) + " " + quoted(dir.file("broken.ini")) + " --quiet --out " +
		quoted(dir.file("o")));
	EXPECT_EQ(r.exitCode, 2) << r.output;
	EXPECT_TRUE(contains(r.output, "broken.ini")) << r.output;
	EXPECT_TRUE(contains(r.output, "INI syntax: Line 3")) << r.output;
	EXPECT_FALSE(fs::exists(dir.file("o")));
	const std::string sim = std::string(VSLAM_BINARY_DIR) + "/bin/vslam-simul-measurements";
	const auto s = runCommand(quoted(sim) + " " + quoted(dir.file("broken.ini")) + " " + quoted(dir.file("s.rawlog")));
	EXPECT_EQ(s.exitCode, 2) << s.output;
	EXPECT_TRUE(contains(s.output, "broken.ini")) << s.output;
	EXPECT_TRUE(contains(s.output, "INI syntax: Line 3")) << s.output;
	EXPECT_FALSE(fs::exists(dir.file("s.rawlog")));
}

TEST(VslamApp, UsageAndMissingConfigurationErrors)
{
	EXPECT_EQ(runCommand(quoted(kVslam)).exitCode, 1);
	EXPECT_EQ(runCommand(quoted(kVslam) + " --help").exitCode, 0);
	EXPECT_EQ(runCommand(quoted(kVslam) + " " + quoted(kDemoIni) + " --frobnicate").exitCode, 1);
	const auto m = runCommand(quoted(kVslam) + " /nonexistent/x.ini");
	EXPECT_EQ(m.exitCode, 2);
	EXPECT_TRUE(contains(m.output, "/nonexistent/x.ini")) << m.output;
	const auto s = runDemo("--set nodot=1");
	EXPECT_EQ(s.exitCode, 2);
	EXPECT_TRUE(contains(s.output, "nodot")) << s.output;
}

TEST(VslamApp, PrintedDefaultConfigurationRunsAsIs)
{
	TempDir dir;
	const auto p = runCommand(quoted(kVslam) + " --print-default-config");
	ASSERT_EQ(p.exitCode, 0);
	std::ofstream(dir.file("default.ini")) << p.output;
	const auto r = runCommand(quoted(kVslam) + " " + quoted(dir.file("default.ini")) + " " + quoted(kDemoRawlog) +
		" --quiet --out " + quoted(dir.file("o")) + " --set vslam.max_steps=50");
	EXPECT_EQ(r.exitCode, 0) << r.output;
}

TEST(VslamApp, WritesASceneAndAPoseGraphThatMrptsOwnReadersOpen)
{
	TempDir dir;
	ASSERT_EQ(runDemo("--out " + quoted(dir.file("o")) + " --set vslam.max_steps=1500").exitCode, 0);
	// final_map.3Dscene, as SceneViewer3D loads it.
	mrpt::opengl::COpenGLScene scene;
	ASSERT_TRUE(scene.loadFromFile(dir.file("o/final_map.3Dscene")));
	size_t ellipses = 0, estimateSegments = 0, truthSegments = 0;
	for (const auto& obj : *scene.getViewport())
	{
		if (const auto lines = std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(obj))
		{
			if (lines->getName() == "landmark") ellipses++;
			if (lines->getName() == "estimate") estimateSegments = lines->size();
			if (lines->getName() == "ground truth") truthSegments = lines->size();
		}
	}
	EXPECT_EQ(ellipses, readLandmarkMap(dir.file("o/final_map.txt"), 0, 0).size());
	EXPECT_GT(ellipses, 5u);
	EXPECT_EQ(estimateSegments, 1499u);  // one per step after the first
	EXPECT_GT(truthSegments, 1000u);
	// pose_graph.graph, as graph-slam reads it.
	mrpt::graphs::CNetworkOfPoses2DInf graph;
	graph.loadFromTextFile(dir.file("o/pose_graph.graph"));
	EXPECT_GT(graph.nodes.size(), ellipses + 1);  // the start, the keyframes and the landmarks
	EXPECT_EQ(readTrajectory(dir.file("o/pose_graph_path.tum")).size(), 1500u);  // the solution at every step
	EXPECT_GE(graph.edgeCount(), graph.nodes.size() - 1);
	if (fs::exists("/usr/bin/graph-slam"))
	{
		const auto info = runCommand("graph-slam --2d --info -i " + quoted(dir.file("o/pose_graph.graph")));
		EXPECT_TRUE(contains(info.output, "Nodes count (in VERTEX2/3 entries) : " + std::to_string(graph.nodes.size())))
			<< info.output;
	}
}

namespace
{
/** Segments of the scene's line set named \a name (0 if none). */
size_t sceneLines(const std::string& sceneFile, const std::string& name)
{
	mrpt::opengl::COpenGLScene scene;
	if (!scene.loadFromFile(sceneFile)) return 0;
	for (const auto& obj : *scene.getViewport())
		if (const auto lines = std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(obj); lines && lines->getName() == name)
			return lines->size();
	return 0;
}
}  // namespace

TEST(VslamApp, TheSceneOfARenderedRawlogShowsTheFloorPlanBesideIt)
{
	TempDir dir;
	// A rendered rawlog comes with NAME_world.world (vslam-simul writes it).
	fs::copy_file(kSource + "/rawlogs/demo_visual.rawlog", dir.file("home.rawlog"));
	fs::copy_file(kSource + "/config_ini/worlds/living_room.world", dir.file("home_world.world"));
	const std::string run = quoted(kVslam) + " " + quoted(kDemoIni) + " " + quoted(dir.file("home.rawlog")) +
		" --quiet --set vslam.max_steps=600 --out ";
	ASSERT_EQ(runCommand(run + quoted(dir.file("o"))).exitCode, 0);
	size_t corners = 0;
	for (const auto& outline : vslam::world::loadFloorPlan(dir.file("home_world.world"), "/usr/share").solidPolygons())
		corners += outline.size();
	EXPECT_GT(corners, 30u);  // 4 walls, 5 boxes
	EXPECT_EQ(sceneLines(dir.file("o/final_map.3Dscene"), "floor plan"), corners);  // every outline closed

	// Drawn offscreen by vslam-eval: the floor plan grey, the estimate blue.
	const auto eval = runCommand(std::string(VSLAM_BINARY_DIR) + "/bin/vslam-eval --run " + quoted(dir.file("o")) + " " +
		quoted(kSource + "/rawlogs/demo_visual_groundtruth.tum") + " --scene-png " + quoted(dir.file("scene.png")));
	ASSERT_EQ(eval.exitCode, 0) << eval.output;
	const cv::Mat picture = cv::imread(dir.file("scene.png"));
	ASSERT_EQ(picture.cols, 1200);
	ASSERT_EQ(picture.rows, 900);
	cv::Mat grey, blue;
	cv::inRange(picture, cv::Scalar(100, 100, 100), cv::Scalar(140, 140, 140), grey);
	cv::inRange(picture, cv::Scalar(150, 0, 0), cv::Scalar(255, 60, 60), blue);
	EXPECT_GT(cv::countNonZero(grey), 2000);
	EXPECT_GT(cv::countNonZero(blue), 100);  // a thin line: 235 here

	// One that cannot be read: a warning, and the scene without it.
	std::ofstream(dir.file("home_world.world")) << "wall 0 0 oops\n";
	const auto r = runCommand(run + quoted(dir.file("o2")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_TRUE(contains(r.output, "warning: final_map.3Dscene without the floor plan")) << r.output;
	EXPECT_TRUE(contains(r.output, "home_world.world")) << r.output;
	EXPECT_EQ(sceneLines(dir.file("o2/final_map.3Dscene"), "floor plan"), 0u);
	EXPECT_GT(sceneLines(dir.file("o2/final_map.3Dscene"), "estimate"), 590u);
}

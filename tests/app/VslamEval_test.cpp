/** vslam-eval as users run it: known errors come out exactly, a vslam run
 * gets every figure and the error CSV, bad arguments are one clear error. */
#include <gtest/gtest.h>
#include <libvslam/app/RunSummary.h>
#include <libvslam/io/Trajectory.h>
#include <opencv2/imgcodecs.hpp>
#include <tests/support/RunCommand.h>
#include <tests/support/TempDir.h>

#include <cmath>
#include <fstream>
#include <sstream>

using vslam::testing::contains;
using vslam::testing::lineCount;
using vslam::testing::quoted;
using vslam::testing::runCommand;
using vslam::testing::TempDir;

namespace
{
const std::string kSource = VSLAM_SOURCE_DIR;
const std::string kBin = std::string(VSLAM_BINARY_DIR) + "/bin/";

/** The number after `key ` on the line starting with `line:`. */
double valueOf(const std::string& output, const std::string& line, const std::string& key)
{
	std::istringstream in(output);
	for (std::string l; std::getline(in, l);)
		if (l.rfind(line + ":", 0) == 0)
			if (const auto at = l.find(" " + key + " "); at != std::string::npos)
				return std::stod(l.substr(at + key.size() + 2));
	return NAN;
}

/** Writes truth.tum and estimate.tum in \a dir: 300 poses at 10 Hz from
 * t = 100 s, each file's pose given by its function of the time t and of
 * a = 0.02 rad per pose. Returns the two files as vslam-eval takes them. */
template <class TruthPose, class EstimatePose>
std::string writeTruthAndEstimate(const TempDir& dir, TruthPose truthPose, EstimatePose estimatePose)
{
	vslam::Trajectory truth, estimate;
	for (int i = 0; i < 300; i++)
	{
		const double t = 100 + 0.1 * i, a = 0.02 * i;
		truth.push_back({t, truthPose(t, a)});
		estimate.push_back({t, estimatePose(t, a)});
	}
	vslam::writeTumTrajectory(dir.file("truth.tum"), truth);
	vslam::writeTumTrajectory(dir.file("estimate.tum"), estimate);
	return quoted(dir.file("estimate.tum")) + " " + quoted(dir.file("truth.tum"));
}

/** The unit circle, driven forwards. */
mrpt::math::TPose2D onTheCircle(double, double a) { return {std::cos(a), std::sin(a), a + M_PI / 2}; }
}  // namespace

TEST(VslamEval, AShiftedEstimateHasExactlyItsShiftAsAbsoluteErrorAndNoRelativeError)
{
	TempDir dir;
	const std::string files = writeTruthAndEstimate(dir, onTheCircle, [](double t, double a) {
		return mrpt::math::TPose2D(std::cos(a) + 0.3, std::sin(a) - 0.4, a + M_PI / 2);
	});
	const auto r = runCommand(kBin + "vslam-eval " + files + " --rpe-time 2 --rpe-distance 0.5 --csv " + quoted(dir.file("errors.csv")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_NEAR(valueOf(r.output, "ate", "rmse"), 0.5, 1e-4) << r.output;
	EXPECT_NEAR(valueOf(r.output, "ate", "max"), 0.5, 1e-4) << r.output;
	EXPECT_NEAR(valueOf(r.output, "ate_se2_aligned", "rmse"), 0, 1e-4) << r.output;
	EXPECT_NEAR(valueOf(r.output, "rpe_2s", "trans_max"), 0, 1e-4) << r.output;
	EXPECT_EQ(valueOf(r.output, "rpe_2s", "pairs"), 280) << r.output;
	EXPECT_NEAR(valueOf(r.output, "rpe_0.5m", "rot_rmse_deg"), 0, 1e-3) << r.output;
	EXPECT_EQ(lineCount(dir.file("errors.csv")), 301u);  // header + one row per pose
	// A shift is no stretch: the similarity finds scale 1 and no error.
	EXPECT_NEAR(valueOf(r.output, "ate_sim2_aligned", "scale"), 1, 1e-4) << r.output;
	EXPECT_NEAR(valueOf(r.output, "ate_sim2_aligned", "rmse"), 0, 1e-4) << r.output;
}

TEST(VslamEval, FromAndToScoreOnlyThePartOfTheRunBetweenThem)
{
	// Exact for its first 20 s, then 0.4 m off: each part scored alone
	// has exactly its own error, the odometry is windowed the same way.
	TempDir dir;
	const std::string files = writeTruthAndEstimate(dir, onTheCircle, [](double t, double a) {
		return mrpt::math::TPose2D(std::cos(a) + (t >= 120 ? 0.4 : 0), std::sin(a), a + M_PI / 2);
	});
	const std::string odometry = " --odometry " + quoted(dir.file("estimate.tum"));
	const auto first = runCommand(kBin + "vslam-eval " + files + odometry + " --to 20");
	ASSERT_EQ(first.exitCode, 0) << first.output;
	EXPECT_EQ(valueOf(first.output, "ate", "poses"), 200) << first.output;
	EXPECT_NEAR(valueOf(first.output, "ate", "max"), 0, 1e-4) << first.output;
	EXPECT_EQ(valueOf(first.output, "odometry_ate", "poses"), 200) << first.output;
	const auto later = runCommand(kBin + "vslam-eval " + files + " --from 20");
	ASSERT_EQ(later.exitCode, 0) << later.output;
	EXPECT_EQ(valueOf(later.output, "ate", "poses"), 100) << later.output;
	EXPECT_NEAR(valueOf(later.output, "ate", "median"), 0.4, 1e-4) << later.output;
	// A window with nothing in it, or the wrong way round, is one clear error.
	const auto empty = runCommand(kBin + "vslam-eval " + files + " --from 40 --to 50");
	EXPECT_NE(empty.exitCode, 0);
	EXPECT_TRUE(contains(empty.output, "no pose between --from and --to")) << empty.output;
	const auto reversed = runCommand(kBin + "vslam-eval " + files + " --from 20 --to 10");
	EXPECT_NE(reversed.exitCode, 0);
	EXPECT_TRUE(contains(reversed.output, "--from must be before --to")) << reversed.output;
}

TEST(VslamEval, AnEstimateTooLargeIsExplainedByTheSimilarityWithItsScale)
{
	// The estimate 2% too large about the truth's start: its SE(2)-aligned
	// error stays; the similarity line gives the scale back (1 / 1.02) and
	// no error.
	TempDir dir;
	const std::string files = writeTruthAndEstimate(
		dir, [](double, double a) { return mrpt::math::TPose2D(2 * std::cos(a), std::sin(a), a); },
		[](double, double a) { return mrpt::math::TPose2D(2 + 1.02 * (2 * std::cos(a) - 2), 1.02 * std::sin(a), a); });
	const auto r = runCommand(kBin + "vslam-eval " + files);
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_GT(valueOf(r.output, "ate_se2_aligned", "rmse"), 0.01) << r.output;
	EXPECT_NEAR(valueOf(r.output, "ate_sim2_aligned", "scale"), 1 / 1.02, 1e-4) << r.output;
	EXPECT_NEAR(valueOf(r.output, "ate_sim2_aligned", "rmse"), 0, 1e-4) << r.output;
	EXPECT_NEAR(valueOf(r.output, "ate_sim2_aligned", "heading_rmse_deg"), 0, 1e-3) << r.output;
}

TEST(VslamEval, AVslamRunGetsEveryFigureAndTheOdometryBesideIt)
{
	TempDir dir;
	const std::string out = dir.file("run");
	const auto run = runCommand(kBin + "vslam " + quoted(kSource + "/config_ini/demo_visual.ini") + " --quiet --out " +
		quoted(out) + " --set vslam.max_steps=400");
	ASSERT_EQ(run.exitCode, 0) << run.output;
	const std::string truth = kSource + "/rawlogs/demo_visual_groundtruth.tum";
	const auto r = runCommand(kBin + "vslam-eval --run " + quoted(out) + " " + quoted(truth) + " --csv " +
		quoted(dir.file("e.csv")) + " --landmarks " + quoted(kSource + "/rawlogs/demo_visual_landmarks.txt"));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	for (const char* line : {"ate", "ate_se2_aligned", "ate_sim2_aligned", "odometry_ate", "odometry_ate_se2_aligned",
			 "odometry_ate_sim2_aligned"})
		EXPECT_EQ(valueOf(r.output, line, "poses"), 400) << line << "\n" << r.output;
	// The map against the simulator's landmarks: every mapped landmark has
	// its true partner (same IDs).
	const double mapped = valueOf(r.output, "map", "landmarks");
	EXPECT_GT(mapped, 3) << r.output;
	EXPECT_EQ(valueOf(r.output, "map", "matched"), mapped) << r.output;
	EXPECT_EQ(valueOf(r.output, "map_se2_aligned", "matched"), mapped) << r.output;
	for (const char* line : {"rpe_1s", "odometry_rpe_1s"})
		EXPECT_GT(valueOf(r.output, line, "pairs"), 300) << line << "\n" << r.output;
	// The estimate's ATE is the one the run itself reported.
	const auto summary = vslam::readRunSummary(out + "/run_summary.yaml");
	EXPECT_EQ(vslam::summaryNumber(summary, "error_vs_ground_truth_m.vslam.associated_poses"), 400);
	EXPECT_NEAR(valueOf(r.output, "ate", "rmse"), vslam::summaryNumber(summary, "error_vs_ground_truth_m.vslam.rmse"), 1e-4)
		<< r.output;
	EXPECT_EQ(lineCount(dir.file("e.csv")), 801u);  // estimate and odometry, 400 rows each
	for (const char* f : {"paths", "error_over_time", "measurements_per_landmark", "particle_spread", "dual_ratio"})
	{
		const cv::Mat img = cv::imread(out + "/figures/" + f + ".png");
		EXPECT_FALSE(img.empty()) << f;
		EXPECT_GT(img.cols, 300) << f;
	}
}

TEST(VslamEval, BadArgumentsAreOneClearError)
{
	TempDir dir;
	vslam::writeTumTrajectory(dir.file("t.tum"), {{1, {0, 0, 0}}, {2, {1, 0, 0}}});
	const auto zero = runCommand(kBin + "vslam-eval " + quoted(dir.file("t.tum")) + " " + quoted(dir.file("t.tum")) +
		" --rpe-time 0");
	EXPECT_EQ(zero.exitCode, 1);
	EXPECT_TRUE(contains(zero.output, "--rpe-time needs a positive number")) << zero.output;
	const auto typo = runCommand(kBin + "vslam-eval " + quoted(dir.file("t.tum")) + " " + quoted(dir.file("t.tum")) +
		" --rpe-tme 1");
	EXPECT_EQ(typo.exitCode, 1);
	EXPECT_TRUE(contains(typo.output, "unknown option '--rpe-tme'")) << typo.output;
	const auto noRun = runCommand(kBin + "vslam-eval --run " + quoted(dir.file("nothing")) + " " + quoted(dir.file("t.tum")));
	EXPECT_EQ(noRun.exitCode, 3);
	EXPECT_TRUE(contains(noRun.output, "nothing/estimated_path.tum")) << noRun.output;
}

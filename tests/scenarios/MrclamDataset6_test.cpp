/** Real data: MRCLAM Dataset 6, robots 1 and 2 (15-20 minutes, Vicon truth),
 * through the importer and the filter with the shipped INI
 * (config_ini/mrclam_range_bearing.ini, the same for every robot). Skipped
 * when ../shared is absent. */
#include <gtest/gtest.h>
#include <libvslam/app/KeyframesAlongOdometry.h>
#include <libvslam/config/IniText.h>
#include <libvslam/core/ActionOdometry.h>
#include <libvslam/eval/AbsoluteTrajectoryError.h>
#include <libvslam/filter/CVSlamParticleFilter.h>
#include <libvslam/io/MrclamImporter.h>
#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/random/RandomGenerators.h>
#include <tests/support/SharedData.h>

#include <fstream>
#include <sstream>

using namespace vslam;

namespace
{
struct RobotRun
{
	Trajectory estimate, odometry, smoothed, truth;
};

/** One robot through the importer and the filter; smoothed: the
 * loop-closure graph solved at the end, at every step. */
RobotRun runRobot(const std::filesystem::path& dir, int robot)
{
	TMrclamImportOptions io;
	io.robot = robot;
	const MrclamImport im = importMrclam(dir.string(), io);

	std::ifstream in(std::string(VSLAM_SOURCE_DIR) + "/config_ini/mrclam_range_bearing.ini");
	std::stringstream text;
	text << in.rdbuf();
	const mrpt::config::CConfigFileMemory ini(text.str());
	CVSlamParticleFilter::TOptions opts;
	opts.loadFromConfig(ini);
	EXPECT_EQ(opts.pf.sampleSize, 1000u);

	mrpt::random::getRandomGenerator().randomize(1);
	CVSlamParticleFilter filter(opts);
	mrpt::bayes::CParticleFilter pf;
	pf.m_options = opts.pf.toMrpt();
	RobotRun run;
	run.truth = im.groundTruth;
	se2::Pose odo = opts.pf.initialPose;
	for (const auto& [actions, sf] : im.steps)
	{
		pf.executeOn(filter, actions.get(), sf.get());
		odo = se2::compose(odo, odometryIncrement(*actions)->asTPose());
		const double t = mrpt::Clock::toDouble(
			actions->getActionByClass<mrpt::obs::CActionRobotMovement2D>()->timestamp);
		run.estimate.push_back({t, filter.meanPose()});
		run.odometry.push_back({t, odo});
	}
	if (const CLandmarkPoseGraph* graph = filter.loopClosureGraph())
	{
		CLandmarkPoseGraph solved = *graph;
		solved.optimize();
		Trajectory keyframes;
		for (const auto& [t, pose] : solved.keyframePath()) keyframes.push_back({mrpt::Clock::toDouble(t), pose});
		run.smoothed = keyframesAlongOdometry(keyframes, run.odometry);
	}
	return run;
}

bool skipWithoutData(const std::filesystem::path& dir)
{
	return !std::filesystem::exists(dir / "Robot1_Odometry.dat");
}
}  // namespace

TEST(MrclamDataset6, Robot1ErrorFarBelowDeadReckoning)
{
	const auto dir = vslam::testing::mrclamDataset(6);
	if (skipWithoutData(dir)) GTEST_SKIP() << "MRCLAM data absent (" << dir << "): real-data test skipped";
	const RobotRun run = runRobot(dir, 1);
	const AteStats vslam = computeAte(run.estimate, run.truth);
	const AteStats deadReckoning = computeAte(run.odometry, run.truth);
	std::printf("MRCLAM D6 R1: ATE RMSE vslam %.3f m, dead reckoning %.3f m (%zu poses)\n",
		vslam.rmse, deadReckoning.rmse, vslam.associated);
	ASSERT_GT(vslam.associated, 3000u);  // 20 min of steps at image or gap rate
	// Measured, seeds 1-5: 0.24-0.25 m; dead reckoning 2.66 m; kf-slam 0.26 m.
	EXPECT_LT(vslam.rmse, 0.35);
	EXPECT_LT(vslam.rmse, 0.2 * deadReckoning.rmse);
	EXPECT_GT(deadReckoning.rmse, 1.0);
}

TEST(MrclamDataset6, Robot2SmoothedPathBeatsTheEkf)
{
	// Robot 2 is where the online estimate trails MRPT's EKF (0.44 against
	// 0.28 m): a 25 degree heading error after a blind stretch that only
	// old landmarks, 30 s later, can undo. The graph solved over the whole
	// run undoes it everywhere: measured 0.17 m (seeds 1-5), the full batch
	// least squares 0.17 m.
	const auto dir = vslam::testing::mrclamDataset(6);
	if (skipWithoutData(dir)) GTEST_SKIP() << "MRCLAM data absent (" << dir << "): real-data test skipped";
	const RobotRun run = runRobot(dir, 2);
	const AteStats online = computeAte(run.estimate, run.truth);
	const AteStats smoothed = computeAte(run.smoothed, run.truth);
	std::printf("MRCLAM D6 R2: ATE RMSE online %.3f m, smoothed %.3f m (%zu poses)\n", online.rmse,
		smoothed.rmse, smoothed.associated);
	EXPECT_EQ(smoothed.associated, online.associated);  // every step, as the estimate
	constexpr double kKfSlam = 0.28;
	EXPECT_LT(smoothed.rmse, 0.22);
	EXPECT_LT(smoothed.rmse, kKfSlam);
	EXPECT_LT(smoothed.rmse, 0.6 * online.rmse);
}

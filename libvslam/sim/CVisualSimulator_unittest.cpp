/** The rendered simulator against its own specification: determinism, the
 * laser against the floor plan, odometry errors with the configured
 * statistics, the calibration and mount in every image, events, and bad
 * scenarios. Uses the shipped living room (textures from the packages the
 * set-up script installs). */
#include <gtest/gtest.h>
#include <libvslam/core/InputError.h>
#include <libvslam/sim/CVisualSimulator.h>
#include <libvslam/world/FloorPlanFile.h>
#include <libvslam/world/FreeSpace.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>
#include <opencv2/imgcodecs.hpp>
#include <tests/support/TempDir.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace vslam;
namespace fs = std::filesystem;

namespace
{
const std::string kWorlds = std::string(VSLAM_SOURCE_DIR) + "/config_ini/worlds/";

CVisualSimulator::TOptions shortRun(double duration)
{
	CVisualSimulator::TOptions o;
	o.world_file = kWorlds + "living_room.world";
	o.texture_max_side = 512;  // enough for these checks, light on memory
	o.duration = duration;
	o.start_pose = {2.0, 1.0, 30};
	return o;
}

world::FloorPlan livingRoom(const CVisualSimulator::TOptions& o) { return world::loadFloorPlan(o.world_file, o.texture_dir); }

std::string fileBytes(const fs::path& p)
{
	std::ifstream in(p, std::ios::binary);
	return {std::istreambuf_iterator<char>(in), {}};
}

const mrpt::obs::CActionRobotMovement2D* odometryOf(const ActionFramePair& e)
{
	return e.first->getBestMovementEstimation().get();
}
}  // namespace

TEST(CVisualSimulator, SameSeedSameRawlogAndImages)
{
	const CVisualSimulator::TOptions o = shortRun(8);
	const auto plan = livingRoom(o);
	vslam::testing::TempDir a, b;
	const auto runA = CVisualSimulator(o, plan).run(a.path().string());
	const auto runB = CVisualSimulator(o, plan).run(b.path().string());
	writeActionFrameRawlog((a.path() / "r.rawlog").string(), runA.entries);
	writeActionFrameRawlog((b.path() / "r.rawlog").string(), runB.entries);
	EXPECT_EQ(fileBytes(a.path() / "r.rawlog"), fileBytes(b.path() / "r.rawlog"));
	size_t images = 0;
	for (const auto& e : fs::directory_iterator(a.path()))
		if (e.path().extension() == ".jpg")
		{
			EXPECT_EQ(fileBytes(e.path()), fileBytes(b.path() / e.path().filename())) << e.path();
			images++;
		}
	EXPECT_EQ(images, runA.images);
	EXPECT_EQ(runA.images, 20u);  // 8 s at 2.5 Hz

	CVisualSimulator::TOptions other = o;
	other.seed = 2;
	vslam::testing::TempDir c;
	const auto runC = CVisualSimulator(other, plan).run(c.path().string());
	EXPECT_NE(runC.truePath.back().pose.x, runA.truePath.back().pose.x);
}

TEST(CVisualSimulator, LaserRangesEndOnTheFloorPlanAndImagesCarryTheCalibration)
{
	CVisualSimulator::TOptions o = shortRun(30);
	o.camera_mount = {0.12, -0.02, 0.4, 3, -8, 1};
	const auto plan = livingRoom(o);
	vslam::testing::TempDir dir;
	const auto run = CVisualSimulator(o, plan).run(dir.path().string());
	const auto segments = plan.obstacleSegments();
	size_t rays = 0, images = 0;
	for (size_t k = 0; k < run.entries.size(); k++)
	{
		const se2::Pose robot = run.truePath[k].pose;
		for (const auto& obs : *run.entries[k].second)
		{
			if (const auto* scan = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(obs.get()))
			{
				ASSERT_EQ(scan->getScanSize(), size_t(o.laser_rays));
				const se2::Pose sensor = se2::compose(robot, {o.laser_pose[0], o.laser_pose[1], 0});
				for (size_t i = 0; i < scan->getScanSize(); i++)
				{
					if (!scan->getScanRangeValidity(i)) continue;
					const double a = sensor.phi - scan->aperture / 2 + scan->aperture * i / (scan->getScanSize() - 1);
					const Eigen::Vector2d end(sensor.x + scan->getScanRange(i) * std::cos(a),
						sensor.y + scan->getScanRange(i) * std::sin(a));
					double d = 1e9;
					for (const auto& s : segments) d = std::min(d, world::pointSegmentDistance(end, s.a, s.b));
					EXPECT_LT(d, 5 * o.laser_std) << "step " << k << " ray " << i;
					rays++;
				}
			}
			if (const auto* img = dynamic_cast<const mrpt::obs::CObservationImage*>(obs.get()))
			{
				EXPECT_EQ(img->cameraParams.intrinsicParams, o.camera.intrinsicParams);
				EXPECT_EQ(img->cameraPose, o.cameraPoseOnRobot());
				EXPECT_TRUE(img->image.isExternallyStored());
				const cv::Mat pixels = cv::imread((dir.path() / img->image.getExternalStorageFile()).string());
				EXPECT_EQ(pixels.cols, int(o.camera.ncols));
				EXPECT_EQ(pixels.rows, int(o.camera.nrows));
				images++;
			}
		}
	}
	EXPECT_GT(rays, 0.95 * 150 * 181);  // nearly every ray of the 150 scans hits something
	EXPECT_EQ(images, 75u);
	// The mount: camera at (0.12, -0.02, 0.4) looking ahead, yawed 3 deg left.
	const auto c = o.cameraPoseOnRobot();
	EXPECT_NEAR(c.x(), 0.12, 1e-12);
	const auto ahead = c.rotateVector(mrpt::math::TVector3D(0, 0, 1));  // the optical axis
	EXPECT_NEAR(std::atan2(ahead.y, ahead.x), 3 * M_PI / 180, 1e-9);
	EXPECT_NEAR(std::asin(ahead.z), 8 * M_PI / 180, 1e-9);  // pitch -8 looks up
}

TEST(CVisualSimulator, OdometryErrorsHaveTheConfiguredStatistics)
{
	// The odometry the rawlog reports against the true motion, per step.
	CVisualSimulator::TOptions o = shortRun(1500);
	o.camera_rate = 0.01;  // one image in 100 s: this is about odometry
	o.odometry.sigma_T = 0.05, o.odometry.sigma_R = 0.05, o.odometry.sigma_R_per_meter = 0.02;
	o.odometry.scale_bias = 0.03, o.odometry.turn_bias = -0.04;
	const auto plan = livingRoom(o);
	vslam::testing::TempDir dir;
	const auto run = CVisualSimulator(o, plan).run(dir.path().string());
	double sumRatioD = 0, sumD = 0, sumZ2 = 0, sumTurn = 0, sumTurnTrue = 0;
	size_t n = 0;
	se2::Pose previous{2.0, 1.0, 30 * M_PI / 180};
	for (size_t k = 0; k < run.entries.size(); k++)
	{
		const se2::Pose truth = se2::between(previous, run.truePath[k].pose);
		previous = run.truePath[k].pose;
		mrpt::poses::CPose2D measured;
		odometryOf(run.entries[k])->poseChange->getMean(measured);
		const double d = std::abs(truth.x);
		if (d > 1e-6)
		{
			// Lateral error: N(0, sigma_T^2 d); normalized, it has variance 1.
			sumZ2 += measured.y() * measured.y() / (o.odometry.sigma_T * o.odometry.sigma_T * d);
			sumRatioD += measured.x(), sumD += truth.x;
			n++;
		}
		else if (std::abs(truth.phi) > 1e-6)
		{
			// Turns both ways: compare magnitudes.
			sumTurn += measured.phi() * (truth.phi > 0 ? 1 : -1), sumTurnTrue += std::abs(truth.phi);
		}
	}
	ASSERT_GT(n, 3000u);
	EXPECT_NEAR(sumZ2 / n, 1.0, 0.1);
	EXPECT_NEAR(sumRatioD / sumD, 1.03, 0.01);
	EXPECT_NEAR(sumTurn / sumTurnTrue, 0.96, 0.02);
}

TEST(CVisualSimulator, KidnapMovesTheRobotUnseenAndEventsShowInTheImages)
{
	CVisualSimulator::TOptions o = shortRun(20);
	o.kidnap_times = {10};
	o.kidnap_min_distance = 2.5;
	o.blackouts = {2, 4};
	o.dark_spells = {6, 8};
	const auto plan = livingRoom(o);
	vslam::testing::TempDir dir;
	const auto run = CVisualSimulator(o, plan).run(dir.path().string());
	ASSERT_EQ(run.kidnapSteps.size(), 1u);
	const size_t k = run.kidnapSteps[0];  // entries[k - 1] is step k
	const auto before = run.truePath[k - 2].pose, after = run.truePath[k - 1].pose;
	EXPECT_GE(std::hypot(after.x - before.x, after.y - before.y), 2.5);
	mrpt::poses::CPose2D measured;
	odometryOf(run.entries[k - 1])->poseChange->getMean(measured);
	EXPECT_LT(measured.norm(), 0.1);  // odometry saw a normal step
	// Mean brightness: only the sensor's noise during the blackout; the
	// first frame of the dark spell dark (the auto-exposure lags), normal
	// again soon after it.
	const auto brightness = [&](double t) {
		const size_t step = static_cast<size_t>(std::lround(t / o.dt));
		return cv::mean(cv::imread((dir.path() / ("img_" + std::to_string(step) + ".jpg")).string()))[0];
	};
	EXPECT_LT(brightness(3.2), 25);
	EXPECT_LT(brightness(6.0), 0.45 * brightness(1.2));  // 0.06 of the light: 0.28 encoded, plus noise
	EXPECT_GT(brightness(9.2), 0.7 * brightness(1.2));
	EXPECT_GT(brightness(1.2), 40);
	EXPECT_EQ(run.blackFrames, 5u);
}

TEST(CVisualSimulator, PathsThroughWallsAreErrorsNamingTheWorldFileLine)
{
	CVisualSimulator::TOptions o = shortRun(10);
	o.path_type = CVisualSimulator::TOptions::PathType::Waypoints;
	o.waypoints = {2.0, 1.2, 2.0, 2.9, 5.0, 2.9};  // the coffee table at (3.6, 1.9)
	const auto plan = livingRoom(o);
	try
	{
		CVisualSimulator(o, plan);
		FAIL() << "no error";
	}
	catch (const InputError& e)
	{
		EXPECT_NE(std::string(e.what()).find("the leg from point 3 (5.00, 2.90) -> (2.00, 1.20)"), std::string::npos)
			<< e.what();
		EXPECT_NE(std::string(e.what()).find("line 18 of world file"), std::string::npos) << e.what();
	}
	o.waypoints = {2.0, 1.2, 12.0, 1.2};  // out through the east wall
	EXPECT_THROW(CVisualSimulator(o, plan), InputError);
	o.path_type = CVisualSimulator::TOptions::PathType::Random;
	o.start_pose = {3.6, 1.9, 0};  // inside the coffee table
	EXPECT_THROW(CVisualSimulator(o, plan), InputError);
	o.start_pose = {2.0, 1.0, 0};
	o.people = {1, 1.0, 2.0, 6.0, 2.0, 1.0};  // walks through the coffee table
	EXPECT_THROW(CVisualSimulator(o, plan), InputError);
}

TEST(CVisualSimulator, TheFloorShakesTheCameraInPitchAndRollNeverInHeading)
{
	CVisualSimulator::TOptions o;
	o.camera_mount = {0.1, 0, 0.85, 0, -5, 0};
	const mrpt::poses::CPose3D mount = o.cameraPoseOnRobot();
	// The optical axis (camera z) and the image's right (camera x) in robot coordinates.
	const auto axis = [](const mrpt::poses::CPose3D& camera, int column) {
		const auto R = camera.getRotationMatrix().asEigen();
		return Eigen::Vector3d(R.col(column));
	};
	const auto azimuth = [](const Eigen::Vector3d& v) { return std::atan2(v.y(), v.x()); };
	const double deg = M_PI / 180;
	// A pitch turns the optical axis up or down, not left or right.
	const mrpt::poses::CPose3D pitched = mount + cameraShake(2 * deg, 0);
	EXPECT_NEAR(azimuth(axis(pitched, 2)), azimuth(axis(mount, 2)), 1e-12);
	EXPECT_NEAR(std::abs(std::asin(axis(pitched, 2).z()) - std::asin(axis(mount, 2).z())), 2 * deg, 1e-9);
	// A roll turns the image about the optical axis, which stays.
	const mrpt::poses::CPose3D rolled = mount + cameraShake(0, 2 * deg);
	EXPECT_NEAR((axis(rolled, 2) - axis(mount, 2)).norm(), 0, 1e-12);
	EXPECT_NEAR(std::acos(axis(rolled, 0).dot(axis(mount, 0))), 2 * deg, 1e-9);
}

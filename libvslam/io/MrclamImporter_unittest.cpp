#include <gtest/gtest.h>
#include <libvslam/core/ActionOdometry.h>
#include <libvslam/core/InputError.h>
#include <libvslam/io/MrclamImporter.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <tests/support/SharedData.h>
#include <tests/support/TempDir.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace vslam;
using vslam::testing::TempDir;

namespace
{
/** A tiny data set: robot 1 drives 1 m straight at 0.1 m/s (odometry at
 * 100 Hz) from world pose (2, 1, pi/2) at t = 100 s, sees landmark 6 at
 * t = 102 s (when it is at (2, 1.2)) and t = 105 s, plus a false barcode
 * and another robot. */
void writeDataset(const std::string& dir)
{
	std::ofstream(dir + "/Barcodes.dat") << "# Subject # Barcode #\n1 5\n2 14\n6 63\n7 27\n";
	std::ofstream(dir + "/Landmark_Groundtruth.dat") << "# header\n6 2.0 4.0 0.0 0.0\n7 0 0 0 0\n";
	std::ofstream odo(dir + "/Robot1_Odometry.dat");
	odo << "# Time v omega\n";
	for (int i = 0; i <= 1000; i++) odo << 100.0 + 0.01 * i << " 0.1 0.0\n";
	std::ofstream gt(dir + "/Robot1_Groundtruth.dat");
	gt << "# Time x y theta\n";
	for (int i = 0; i <= 110; i++) gt << 99.5 + 0.1 * i << " 2.0 " << 1.0 + 0.01 * (i - 5) * (i >= 5) << " 1.5707963\n";
	std::ofstream(dir + "/Robot1_Measurement.dat")
		<< "# Time barcode range bearing\n"
		<< "102.0 63 2.8 0.0\n"  // landmark 6, 2.8 m ahead
		<< "102.0 43 1.0 0.1\n"  // false barcode
		<< "103.0 14 2.0 0.2\n"  // robot 2
		<< "105.0 63 2.5 0.0\n";
}
}  // namespace

TEST(MrclamImporter, ConvertsOdometryMeasurementsAndGroundTruth)
{
	TempDir dir;
	writeDataset(dir.path().string());
	TMrclamImportOptions o;
	o.max_step_gap = 0.5;
	o.odometry_delay = 0.0;
	const MrclamImport im = importMrclam(dir.path().string(), o);
	EXPECT_EQ(im.odometryRows, 1001u);
	EXPECT_EQ(im.measurementRows, 4u);
	EXPECT_EQ(im.measurementsUsed, 2u);
	EXPECT_EQ(im.droppedFalseBarcodes, 1u);
	EXPECT_EQ(im.droppedRobotSightings, 1u);
	// The start is the first image with a landmark: t = 102 s.
	EXPECT_NEAR(im.startPoseWorld.x, 2.0, 1e-9);
	EXPECT_NEAR(im.startPoseWorld.y, 1.2, 1e-9);

	// Increments add up to the 0.8 m driven since then, no step is longer
	// than the gap, and the two images are where the measurements are.
	double dist = 0, lastT = 102.0;
	size_t withObs = 0;
	for (const auto& [acts, sf] : im.steps)
	{
		const auto u = odometryIncrement(*acts);
		ASSERT_TRUE(u);
		dist += u->x();
		const double t = mrpt::Clock::toDouble(acts->getActionByClass<mrpt::obs::CActionRobotMovement2D>()->timestamp);
		EXPECT_LE(t - lastT, 0.5 + 1e-6);
		lastT = t;
		auto br = sf->getObservationByClass<mrpt::obs::CObservationBearingRange>();
		ASSERT_TRUE(br);  // kf-slam needs one in every frame
		if (!br->sensedData.empty())
		{
			withObs++;
			ASSERT_EQ(br->sensedData.size(), 1u);
			EXPECT_EQ(br->sensedData[0].landmarkID, 6);
		}
	}
	EXPECT_NEAR(dist, 0.8, 1e-9);
	EXPECT_EQ(withObs, 2u);

	// Start frame: the robot faces +x, the landmark is 2.8 m ahead.
	const auto startGt = interpolate(im.groundTruth, 102.0, 1.0);
	ASSERT_TRUE(startGt);
	EXPECT_NEAR(startGt->x, 0.0, 1e-6);
	ASSERT_EQ(im.landmarks.size(), 2u);
	EXPECT_EQ(im.landmarks[0].subject, 6);
	EXPECT_NEAR(im.landmarks[0].x, 2.8, 1e-6);
	EXPECT_NEAR(im.landmarks[0].y, 0.0, 1e-6);
	const auto end = interpolate(im.groundTruth, 110.0, 1.0);
	ASSERT_TRUE(end);
	EXPECT_NEAR(end->x, 0.8, 1e-6);
}

TEST(MrclamImporter, BadInputNamesTheFile)
{
	TempDir dir;
	writeDataset(dir.path().string());
	std::ofstream(dir.file("Robot1_Odometry.dat"), std::ios::app) << "101.0 abc 0\n";
	try
	{
		importMrclam(dir.path().string(), {});
		FAIL();
	}
	catch (const InputError& e)
	{
		EXPECT_NE(std::string(e.what()).find("Robot1_Odometry.dat"), std::string::npos) << e.what();
		EXPECT_NE(std::string(e.what()).find("line 1003"), std::string::npos) << e.what();
	}
	EXPECT_THROW(importMrclam(dir.file("missing"), {}), InputError);
	TMrclamImportOptions o;
	o.robot = 6;
	EXPECT_THROW(importMrclam(dir.path().string(), o), InputError);
}

namespace
{
std::string importError(const std::string& dir)
{
	try
	{
		importMrclam(dir, {});
	}
	catch (const InputError& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

// Found by fuzz_mrclam: a barcode of 2.2e38 was cast to int (undefined
// behaviour); a corrupt time far in the future would have asked for
// billions of gap-filling steps.
TEST(MrclamImporter, NonIntegerIdsAndAbsurdTimeSpansNameTheFile)
{
	for (const char* row : {"106.0 2.2e38 1.0 0.1\n", "106.0 63.5 1.0 0.1\n"})
	{
		TempDir dir;
		writeDataset(dir.path().string());
		std::ofstream(dir.file("Robot1_Measurement.dat"), std::ios::app) << row;
		const std::string e = importError(dir.path().string());
		EXPECT_NE(e.find("Robot1_Measurement.dat': data row 5: expected an integer ID"), std::string::npos) << e;
	}
	{
		TempDir dir;
		writeDataset(dir.path().string());
		std::ofstream(dir.file("Barcodes.dat"), std::ios::app) << "8 1e300\n";
		const std::string e = importError(dir.path().string());
		EXPECT_NE(e.find("Barcodes.dat': data row 5"), std::string::npos) << e;
	}
	{
		TempDir dir;
		writeDataset(dir.path().string());
		std::ofstream(dir.file("Robot1_Odometry.dat"), std::ios::app) << "1e15 0.1 0.0\n";
		const std::string e = importError(dir.path().string());
		EXPECT_NE(e.find("Robot1_Odometry.dat': odometry spans"), std::string::npos) << e;
	}
}

TEST(MrclamImporter, RealDataset6Robot1)
{
	const std::filesystem::path dir = vslam::testing::mrclamDataset(6);
	if (!std::filesystem::exists(dir / "Robot1_Odometry.dat"))
		GTEST_SKIP() << "MRCLAM data absent (" << dir << "): real-data test skipped";
	TMrclamImportOptions o;
	o.odometry_delay = 0.0;
	const MrclamImport im = importMrclam(dir.string(), o);
	EXPECT_EQ(im.landmarks.size(), 15u);
	EXPECT_GT(im.measurementsUsed, 1000u);
	EXPECT_GT(im.droppedFalseBarcodes, 0u);  // e.g. barcode 43 (README)
	// Dead reckoning drifts about 0.5 m in the first 90 s (README).
	se2::Pose odo{0, 0, 0};
	double driftAt90 = -1;
	for (const auto& [acts, sf] : im.steps)
	{
		odo = se2::compose(odo, odometryIncrement(*acts)->asTPose());
		const double t = mrpt::Clock::toDouble(acts->getActionByClass<mrpt::obs::CActionRobotMovement2D>()->timestamp);
		if (driftAt90 < 0 && t > 1248444187.156 + 90)
		{
			const auto gt = interpolate(im.groundTruth, t, 1.0);
			ASSERT_TRUE(gt);
			driftAt90 = std::hypot(gt->x - odo.x, gt->y - odo.y);
		}
	}
	EXPECT_GT(driftAt90, 0.2);
	EXPECT_LT(driftAt90, 1.0);
}

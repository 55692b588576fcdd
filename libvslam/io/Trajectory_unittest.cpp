#include <gtest/gtest.h>
#include <libvslam/core/InputError.h>
#include <libvslam/io/Trajectory.h>
#include <tests/support/TempDir.h>

#include <fstream>
#include <limits>

using namespace vslam;

TEST(Trajectory, TumRoundTripAndFormatDetection)
{
	vslam::testing::TempDir dir;
	Trajectory tr;
	for (int i = 0; i < 10; i++) tr.push_back({1700000000.0 + 0.5 * i, {0.1 * i, 1.0, -3.0 + 0.6 * i}});
	writeTumTrajectory(dir.file("a.tum"), tr);
	const Trajectory back = readTrajectory(dir.file("a.tum"));
	ASSERT_EQ(back.size(), tr.size());
	for (size_t i = 0; i < tr.size(); i++)
	{
		EXPECT_NEAR(back[i].t, tr[i].t, 1e-6);
		EXPECT_NEAR(back[i].pose.x, tr[i].pose.x, 1e-6);
		EXPECT_NEAR(se2::wrap(back[i].pose.phi - tr[i].pose.phi), 0, 1e-6);
	}
	std::ofstream(dir.file("r.txt")) << "0 1.0 2.0 0 0.5 0 0 1700000000.5\n"
									 << "1 1.5 2.0 0 0.6 0 0 1700000001.5\n";
	const Trajectory r = readTrajectory(dir.file("r.txt"));
	ASSERT_EQ(r.size(), 2u);
	EXPECT_NEAR(r[1].t, 1700000001.5, 1e-6);
	EXPECT_NEAR(r[1].pose.phi, 0.6, 1e-12);
}

TEST(Trajectory, InterpolationUsesTheShortestArc)
{
	const Trajectory tr = {{0, {0, 0, 3.0}}, {1, {1, 0, -3.0}}};
	const auto p = interpolate(tr, 0.5, 2.0);
	ASSERT_TRUE(p);
	EXPECT_NEAR(p->x, 0.5, 1e-12);
	EXPECT_NEAR(std::abs(p->phi), M_PI, 1e-9);
	EXPECT_FALSE(interpolate(tr, 1.5, 2.0));
	EXPECT_FALSE(interpolate(tr, 0.5, 0.5));  // gap too long
}

TEST(Trajectory, MalformedFilesNameTheLine)
{
	vslam::testing::TempDir dir;
	std::ofstream(dir.file("bad.tum")) << "# header\n1 2 3 4 5 6 7 8\n1 2 x 4 5 6 7 8\n";
	std::ofstream(dir.file("short.tum")) << "1 2 3 4 5 6 7 8\n1 2 3\n";
	EXPECT_THROW(readTumTrajectory(dir.file("short.tum")), InputError);
	try
	{
		readTumTrajectory(dir.file("bad.tum"));
		FAIL();
	}
	catch (const InputError& e)
	{
		EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
	}
	EXPECT_THROW(readTumTrajectory(dir.file("missing.tum")), InputError);
}

TEST(Trajectory, ALastRowCutByAKilledWriterIsSkippedOnlyIfUnterminated)
{
	vslam::testing::TempDir dir;
	// What SIGKILL can leave: the last row cut mid-write, without its newline.
	std::ofstream(dir.file("cut.txt")) << "% step x y z yaw pitch roll t\n0 0 0 0 0 0 0 1.5\n1 0.1 0 0 0 0 0 2.0\n2 0.2";
	EXPECT_EQ(readRbpfSlamPath(dir.file("cut.txt")).size(), 2u);
	std::ofstream(dir.file("cut2.tum")) << "1 2 3 4 5 6 7 8\n2 2 3 4 5 6 7 8\n3 2 3 4 5 6 7 0.9x";
	EXPECT_EQ(readTumTrajectory(dir.file("cut2.tum")).size(), 2u);
	// A whole last row without its newline is data.
	std::ofstream(dir.file("whole.tum")) << "1 2 3 4 5 6 7 8\n2 2 3 4 5 6 7 8";
	EXPECT_EQ(readTumTrajectory(dir.file("whole.tum")).size(), 2u);
	// With its newline, a short row is an error as before.
	std::ofstream(dir.file("short.tum")) << "1 2 3 4 5 6 7 8\n2 2 3\n";
	EXPECT_THROW(readTumTrajectory(dir.file("short.tum")), InputError);
}

TEST(Trajectory, MrptPoseListsAreIndexedBySteps)
{
	vslam::testing::TempDir dir;
	std::ofstream(dir.file("gt.txt")) << "% Columns are: x(m) y(m) z(m) yaw(rad) pitch(rad) roll(rad)\n"
									  << "0 0 0 0 0 0\n"
									  << "1.5 -2 0 0.25 0 0\n";
	const Trajectory gt = readTrajectory(dir.file("gt.txt"));
	ASSERT_EQ(gt.size(), 2u);
	EXPECT_EQ(gt[1].step, 1);
	EXPECT_TRUE(std::isnan(gt[1].t));
	EXPECT_NEAR(gt[1].pose.y, -2, 1e-12);
	EXPECT_NEAR(gt[1].pose.phi, 0.25, 1e-12);
	std::ofstream(dir.file("r.txt")) << "7 1.0 2.0 0 0.5 0 0 1700000000.5\n";
	EXPECT_EQ(readTrajectory(dir.file("r.txt"))[0].step, 7);
}

TEST(Trajectory, ATimeWindowKeepsThePosesFromItsStartUpToItsEnd)
{
	Trajectory tr;
	for (int i = 0; i < 10; i++) tr.push_back({100.0 + i, {double(i), 0, 0}});
	const Trajectory middle = timeWindow(tr, 100, 2, 5);  // 102, 103, 104: start in, end out
	ASSERT_EQ(middle.size(), 3u);
	EXPECT_EQ(middle.front().t, 102);
	EXPECT_EQ(middle.back().t, 104);
	EXPECT_EQ(timeWindow(tr, 100, 7, std::numeric_limits<double>::infinity()).size(), 3u);
	EXPECT_TRUE(timeWindow(tr, 100, 20, 30).empty());
	// Poses without a time: only the whole run keeps them.
	Trajectory steps{{std::nan(""), {0, 0, 0}, 0}, {std::nan(""), {1, 0, 0}, 1}};
	EXPECT_EQ(timeWindow(steps, 0, 0, std::numeric_limits<double>::infinity()).size(), 2u);
	EXPECT_TRUE(timeWindow(steps, 0, 0, 10).empty());
}

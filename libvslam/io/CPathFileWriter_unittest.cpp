#include <gtest/gtest.h>
#include <libvslam/io/CPathFileWriter.h>
#include <libvslam/io/Trajectory.h>
#include <tests/support/TempDir.h>

#include <fstream>

using namespace vslam;

TEST(CPathFileWriter, RowsAreReadableWhileTheRunIsStillGoing)
{
	vslam::testing::TempDir dir;
	CPathFileWriter rbpf(dir.file("log_estimated_path.txt"), CPathFileWriter::Format::RbpfSlam);
	CPathFileWriter tum(dir.file("path.tum"), CPathFileWriter::Format::Tum);
	for (int i = 0; i < 5; i++)
	{
		const se2::Pose p{0.1 * i, -0.2 * i, 0.3 * i};
		rbpf.write(i, 1700000000.25 + i, p);
		tum.write(i, 1700000000.25 + i, p);
	}
	// Not closed yet: every row is already on disk.
	const Trajectory a = readRbpfSlamPath(dir.file("log_estimated_path.txt"));
	const Trajectory b = readTumTrajectory(dir.file("path.tum"));
	ASSERT_EQ(a.size(), 5u);
	ASSERT_EQ(b.size(), 5u);
	for (int i = 0; i < 5; i++)
	{
		EXPECT_NEAR(a[i].t, 1700000000.25 + i, 1e-6);
		EXPECT_NEAR(b[i].t, a[i].t, 1e-6);
		EXPECT_NEAR(b[i].pose.phi, 0.3 * i, 1e-6);
		EXPECT_NEAR(a[i].pose.y, -0.2 * i, 1e-6);
	}
	// rbpf-slam's exact row layout.
	std::ifstream in(dir.file("log_estimated_path.txt"));
	std::string first;
	std::getline(in, first);
	EXPECT_EQ(first, "0 0.000000 -0.000000 0.000000 0.000000 0.000000 0.000000 1700000000.250000");
}

TEST(CPathFileWriter, StepsWithAnUnknownPoseAreCommentRowsThePathReadersSkip)
{
	vslam::testing::TempDir dir;
	{
		CPathFileWriter rbpf(dir.file("log_estimated_path.txt"), CPathFileWriter::Format::RbpfSlam);
		CPathFileWriter tum(dir.file("path.tum"), CPathFileWriter::Format::Tum);
		for (int i = 0; i < 4; i++)
		{
			if (i >= 2)  // found at the third step
			{
				rbpf.write(i, 100.0 + i, {1, 2, 0});
				tum.write(i, 100.0 + i, {1, 2, 0});
			}
			else
			{
				rbpf.writeUnknown(i, 100.0 + i);
				tum.writeUnknown(i, 100.0 + i);
			}
		}
		rbpf.close();
		tum.close();
	}
	const Trajectory a = readRbpfSlamPath(dir.file("log_estimated_path.txt"));
	const Trajectory b = readTumTrajectory(dir.file("path.tum"));
	ASSERT_EQ(a.size(), 2u);
	ASSERT_EQ(b.size(), 2u);
	EXPECT_NEAR(a.front().t, 102, 1e-9);
	EXPECT_NEAR(b.front().t, 102, 1e-9);
	std::ifstream in(dir.file("path.tum"));
	std::string line;
	std::getline(in, line);  // the header
	std::getline(in, line);
	EXPECT_EQ(line, "# 100.000000 pose unknown");
}

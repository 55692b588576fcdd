#include <gtest/gtest.h>
#include <libvslam/core/InputError.h>
#include <libvslam/io/LandmarkMapFile.h>
#include <tests/support/TempDir.h>

#include <fstream>

using namespace vslam;
using vslam::testing::TempDir;

TEST(LandmarkMapFile, WrittenMapsReadBackWithTheirCovariances)
{
	TempDir dir;
	LandmarkEstimate pose, point;
	pose.kind = LandmarkKind::Pose;
	pose.mean << 1.5, -2, 0.25;
	pose.cov << 0.01, 0.002, 0.001, 0.002, 0.02, 0.003, 0.001, 0.003, 0.004;
	point.kind = LandmarkKind::Point;
	point.mean << 3, 4, 0;
	point.cov.topLeftCorner<2, 2>() << 0.05, -0.01, -0.01, 0.06;
	const LandmarkMap map{{{LandmarkKind::Pose, 7}, pose},
		{{LandmarkKind::Point, 7}, point}};  // same ID, other kind: another landmark
	writeLandmarkMap(dir.file("map.txt"), map, {34});

	std::vector<uint64_t> measurements;
	const LandmarkMap back = readLandmarkMap(dir.file("map.txt"), 1.0, 1.0, &measurements);
	EXPECT_EQ(measurements, (std::vector<uint64_t>{34, 0}));
	ASSERT_EQ(back.size(), 2u);
	EXPECT_TRUE((back[0].first == LandmarkKey{LandmarkKind::Pose, 7}));
	EXPECT_TRUE((back[1].first == LandmarkKey{LandmarkKind::Point, 7}));
	EXPECT_TRUE(back[0].second.mean.isApprox(pose.mean, 1e-6));
	EXPECT_TRUE(back[0].second.cov.isApprox(pose.cov, 1e-6));
	EXPECT_TRUE(back[1].second.cov.isApprox(point.cov, 1e-6));
	EXPECT_EQ(back[1].second.dim(), 2);
}

TEST(LandmarkMapFile, RowsWithoutCovarianceGetTheGivenUncertainty)
{
	TempDir dir;
	std::ofstream(dir.file("m.txt")) << "% subject x y\n6 -1.5 4.2\n"  // MRCLAM importer
									 << "# id x y phi\n8 1 2 0.5\n"
									 << "9 pose 3 4 1.0 1\n";  // simulator (flag ignored)
	const LandmarkMap m = readLandmarkMap(dir.file("m.txt"), 0.1, 0.02);
	ASSERT_EQ(m.size(), 3u);
	EXPECT_EQ(m[0].second.kind, LandmarkKind::Point);
	EXPECT_DOUBLE_EQ(m[0].second.mean[1], 4.2);
	EXPECT_NEAR(m[0].second.cov(0, 0), 0.01, 1e-15);
	EXPECT_DOUBLE_EQ(m[0].second.cov(2, 2), 0);
	EXPECT_EQ(m[1].second.kind, LandmarkKind::Pose);
	EXPECT_NEAR(m[1].second.cov(2, 2), 0.0004, 1e-15);
	EXPECT_EQ(m[2].first.id, 9);
	EXPECT_DOUBLE_EQ(m[2].second.mean[2], 1.0);
}

TEST(LandmarkMapFile, MalformedMapsNameFileAndLine)
{
	TempDir dir;
	const auto errorOf = [&](const std::string& text) {
		std::ofstream(dir.file("bad.txt")) << text;
		try
		{
			readLandmarkMap(dir.file("bad.txt"), 0.1, 0.1);
		}
		catch (const InputError& e)
		{
			return std::string(e.what());
		}
		return std::string();
	};
	EXPECT_NE(errorOf("1 2 3\n2 x 3\n").find("line 2"), std::string::npos);
	EXPECT_NE(errorOf("1 2 3\n1 4 5\n").find("twice"), std::string::npos);
	EXPECT_NE(errorOf("1 2\n").find("line 1"), std::string::npos);
	EXPECT_NE(errorOf("1.5 2 3\n").find("landmark ID"), std::string::npos);
	EXPECT_NE(errorOf("1e300 2 3\n").find("landmark ID"), std::string::npos);
	EXPECT_NE(errorOf("1 pose 0 0 0 -1 0 0 1 0 1 5\n").find("positive definite"), std::string::npos);
	EXPECT_NE(errorOf("1 point 0 0 0 1 2 0 1 0 0 5\n").find("positive definite"), std::string::npos);
	EXPECT_NE(errorOf("1 pose 2 nan 0\n").find("finite"), std::string::npos);
	EXPECT_THROW(readLandmarkMap(dir.file("missing.txt"), 0.1, 0.1), InputError);
}

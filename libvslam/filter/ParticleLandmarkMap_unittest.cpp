#include <gtest/gtest.h>
#include <libvslam/filter/ParticleLandmarkMap.h>

using namespace vslam;

TEST(ParticleLandmarkMap, KeepsSlotOrderKeysEstimatesAndMeasurementCounts)
{
	CLandmarkIndex index;
	LandmarkBank bank;
	LandmarkEstimate pose, point;
	pose.kind = LandmarkKind::Pose;
	pose.mean << 1.5, -2, 0.25;
	point.kind = LandmarkKind::Point;
	point.mean << 3, 4, 0;
	index.add({LandmarkKind::Pose, 7}, {});
	bank.push_back(pose);
	index.add({LandmarkKind::Point, 7}, {});
	bank.push_back(point);
	index.entry(1).measurements = 12;

	std::vector<uint64_t> measurements{99};  // replaced, not appended to
	const LandmarkMap map = landmarkMapOf(index, bank, &measurements);
	ASSERT_EQ(map.size(), 2u);
	EXPECT_TRUE((map[0].first == LandmarkKey{LandmarkKind::Pose, 7}));
	EXPECT_TRUE((map[1].first == LandmarkKey{LandmarkKind::Point, 7}));
	EXPECT_TRUE(map[0].second.mean.isApprox(pose.mean));
	EXPECT_EQ(map[1].second.kind, LandmarkKind::Point);
	EXPECT_EQ(measurements, (std::vector<uint64_t>{0, 12}));
	EXPECT_EQ(landmarkMapOf(index, bank).size(), 2u);
}

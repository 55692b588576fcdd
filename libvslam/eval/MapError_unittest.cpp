#include <gtest/gtest.h>
#include <libvslam/eval/MapError.h>

using namespace vslam;

namespace
{
std::pair<LandmarkKey, LandmarkEstimate> landmark(LandmarkKind kind, int64_t id, double x, double y, double phi)
{
	LandmarkEstimate l;
	l.kind = kind;
	l.mean << x, y, kind == LandmarkKind::Pose ? phi : 0.0;
	return {{kind, id}, l};
}
}  // namespace

TEST(MapError, LandmarksAreMatchedByKindAndIdAndScoredAfterTheTransform)
{
	const LandmarkMap truth{landmark(LandmarkKind::Pose, 1, 1, 0, 0), landmark(LandmarkKind::Pose, 2, 0, 2, 1.0),
		landmark(LandmarkKind::Point, 1, 3, 3, 0), landmark(LandmarkKind::Point, 9, 5, 5, 0)};
	// The estimate: the truth seen from a frame rotated by 90 deg and moved,
	// with landmark 2 off by 0.3 m and 0.1 rad, and one landmark unknown to
	// the truth.
	const se2::Pose frame{0.5, -1.0, M_PI / 2};
	LandmarkMap estimate;
	for (const auto& [key, l] : truth)
	{
		if (key.id == 9) continue;
		se2::Pose p{l.mean[0], l.mean[1], l.mean[2]};
		if (key.kind == LandmarkKind::Pose && key.id == 2) p.x += 0.3, p.phi += 0.1;
		const se2::Pose seen = se2::compose(se2::inverse(frame), p);
		estimate.push_back(landmark(key.kind, key.id, seen.x, seen.y, seen.phi));
	}
	estimate.push_back(landmark(LandmarkKind::Pose, 7, 0, 0, 0));

	const MapErrorStats raw = computeMapError(estimate, truth);
	EXPECT_EQ(raw.estimated, 4u);
	EXPECT_EQ(raw.truth, 4u);
	EXPECT_EQ(raw.matched, 3u);  // pose 1, pose 2, point 1 (pose 7 and point 9 have no partner)
	EXPECT_GT(raw.position.max, 1.0);
	const MapErrorStats aligned = computeMapError(estimate, truth, frame);
	EXPECT_NEAR(aligned.position.max, 0.3, 1e-9);
	EXPECT_NEAR(aligned.position.median, 0.0, 1e-9);
	EXPECT_EQ(aligned.poses, 2u);
	EXPECT_NEAR(aligned.headingRmse, std::sqrt(0.1 * 0.1 / 2), 1e-9);
}

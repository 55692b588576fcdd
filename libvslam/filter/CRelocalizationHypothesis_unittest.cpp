#include <gtest/gtest.h>
#include <libvslam/filter/CRelocalizationHypothesis.h>
#include <mrpt/random/RandomGenerators.h>
#include <tests/support/Measurements.h>

using namespace vslam;
using namespace vslam::testing;

TEST(CRelocalizationHypothesis, RangeBearingRingCollapsesWithMoreLandmarks)
{
	// One range-bearing measurement leaves a ring of poses; a second
	// landmark picks the right part of it.
	mrpt::random::getRandomGenerator().randomize(12);
	LandmarkBank bank;
	for (const auto& xy : {Eigen::Vector2d(3, 0), Eigen::Vector2d(0, 3)})
	{
		LandmarkEstimate l;
		l.kind = LandmarkKind::Point;
		l.mean << xy, 0;
		l.cov.topLeftCorner<2, 2>() = Eigen::Matrix2d::Identity() * 1e-4;
		bank.push_back(l);
	}
	const se2::Pose truth{0.5, 0.5, 0.3};
	const auto rb = [&](int slot, const Eigen::Vector2d& p) {
		const double dx = p[0] - truth.x, dy = p[1] - truth.y;
		return rangeBearingMeasurement(slot + 1, std::hypot(dx, dy),
			se2::wrap(std::atan2(dy, dx) - truth.phi));
	};
	const auto m1 = rb(0, {3, 0}), m2 = rb(1, {0, 3});
	CRobustLikelihood lik;
	CRelocalizationHypothesis h;
	ASSERT_TRUE(h.start({{&m1, 0, 0}}, bank, 2000, lik, mrpt::random::getRandomGenerator()));
	EXPECT_EQ(h.support(), 1u);
	// Only part of the ring explains the second landmark...
	const double f = h.explainedFraction({{&m2, 1, 0}}, lik);
	EXPECT_GT(f, 0.0);
	EXPECT_LT(f, 0.2);
	// ...and after confirming with it the particles sit on the truth.
	h.confirm({{&m2, 1, 0}}, lik, mrpt::random::getRandomGenerator());
	double sx = 0, sy = 0;
	for (const auto& p : h.poses()) sx += p.x, sy += p.y;
	EXPECT_NEAR(sx / h.poses().size(), truth.x, 0.1);
	EXPECT_NEAR(sy / h.poses().size(), truth.y, 0.1);
	EXPECT_EQ(h.support(), 2u);
	EXPECT_EQ(h.distinctLandmarks(), 2u);
}

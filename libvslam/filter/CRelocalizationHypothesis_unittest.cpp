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
	for (const Eigen::Vector2d& xy : {Eigen::Vector2d(3, 0), Eigen::Vector2d(0, 3)}) bank.push_back(pointLandmark(xy));
	const se2::Pose truth{0.5, 0.5, 0.3};
	const auto m1 = rangeBearingFrom(truth, 1, {3, 0}), m2 = rangeBearingFrom(truth, 2, {0, 3});
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

namespace
{
/** Two pose landmarks, known to a centimetre. */
LandmarkBank twoPoseLandmarks()
{
	LandmarkBank bank;
	for (const se2::Pose& l : {se2::Pose{2, 0, 0}, se2::Pose{0, 2, M_PI / 2}}) bank.push_back(poseLandmark(l));
	return bank;
}

/** The exact pose measurement of bank[slot] from the robot pose `from`,
 * with the given noise. */
LandmarkMeasurement seenFrom(
	const LandmarkBank& bank, size_t slot, const se2::Pose& from, double stdXY,
	double stdPhi)
{
	const auto& m = bank[slot].mean;
	return poseMeasurement(static_cast<int64_t>(slot) + 1,
		se2::between(from, {m[0], m[1], m[2]}), stdXY, stdPhi);
}

/** Share of the poses within `radius` of p (position only). */
double shareNear(const std::vector<se2::Pose>& poses, const se2::Pose& p, double radius)
{
	size_t near = 0;
	for (const auto& s : poses) near += std::hypot(s.x - p.x, s.y - p.y) < radius;
	return double(near) / double(poses.size());
}
}  // namespace

TEST(CRelocalizationHypothesis, EveryMeasurementOfTheFrameWeighsTheSamples)
{
	// The first of two pose measurements (the one the samples are drawn
	// from) is loose, the second sharp: weighted by both, the hypothesis
	// is as sharp as the second.
	mrpt::random::getRandomGenerator().randomize(6);
	const LandmarkBank bank = twoPoseLandmarks();
	const se2::Pose truth{0.3, -0.2, 0.4};
	const auto loose = seenFrom(bank, 0, truth, 0.5, 0.2);
	const auto sharp = seenFrom(bank, 1, truth, 0.02, 0.005);
	CRobustLikelihood lik;
	CRelocalizationHypothesis h;
	ASSERT_TRUE(h.start({{&loose, 0, 0}, {&sharp, 1, 0}}, bank, 2000, lik,
		mrpt::random::getRandomGenerator()));
	EXPECT_GT(shareNear(h.poses(), truth, 0.12), 0.95);
	double sx = 0, sy = 0;
	for (const auto& p : h.poses()) sx += p.x, sy += p.y;
	EXPECT_NEAR(sx / h.poses().size(), truth.x, 0.03);
	EXPECT_NEAR(sy / h.poses().size(), truth.y, 0.03);
	EXPECT_EQ(h.distinctLandmarks(), 2u);
}

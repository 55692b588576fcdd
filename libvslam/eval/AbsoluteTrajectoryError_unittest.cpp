#include <gtest/gtest.h>
#include <libvslam/eval/AbsoluteTrajectoryError.h>
#include <mrpt/random/RandomGenerators.h>

using namespace vslam;

namespace
{
Trajectory circle(double t0, double dt, int n)
{
	Trajectory tr;
	for (int i = 0; i < n; i++)
	{
		const double a = 0.05 * i;
		tr.push_back({t0 + i * dt, {2 * std::cos(a), 2 * std::sin(a), a + M_PI / 2}});
	}
	return tr;
}

Trajectory transformed(const Trajectory& tr, const se2::Pose& T)
{
	Trajectory out = tr;
	for (auto& p : out) p.pose = se2::compose(T, p.pose);
	return out;
}
}  // namespace

TEST(AbsoluteTrajectoryError, IdenticalTrajectoriesHaveNoError)
{
	const auto gt = circle(0, 0.1, 100);
	const auto s = computeAte(gt, gt);
	EXPECT_EQ(s.associated, 100u);
	EXPECT_NEAR(s.rmse, 0, 1e-12);
	EXPECT_NEAR(s.headingRmse, 0, 1e-12);
}

TEST(AbsoluteTrajectoryError, TranslatedAndRotatedEstimates)
{
	const auto gt = circle(0, 0.1, 100);
	const auto shifted = transformed(gt, {1.0, 0, 0});
	EXPECT_NEAR(computeAte(shifted, gt).rmse, 1.0, 1e-9);
	EXPECT_NEAR(computeAte(shifted, gt, {0.5, true}).rmse, 0, 1e-9);
	const auto rotated = transformed(gt, {0.3, -0.2, 0.4});
	EXPECT_GT(computeAte(rotated, gt).rmse, 0.5);
	const auto aligned = computeAte(rotated, gt, {0.5, true});
	EXPECT_NEAR(aligned.rmse, 0, 1e-9);
	EXPECT_NEAR(aligned.headingRmse, 0, 1e-9);
}

TEST(AbsoluteTrajectoryError, AScaledEstimateIsExplainedByTheSimilarityAlone)
{
	// An estimate 3% too large about a point off the path, then moved and
	// turned: the SE(2) alignment leaves the stretch, the similarity
	// finds the scale back (1 / 1.03) and no error.
	const auto gt = circle(0, 0.1, 100);
	auto est = gt;
	for (auto& p : est) p.pose.x = 1.03 * (p.pose.x - 0.7), p.pose.y = 1.03 * (p.pose.y + 0.2);
	est = transformed(est, {0.3, -0.2, 0.4});
	const auto rigid = computeAte(est, gt, {0.5, true, false});
	EXPECT_GT(rigid.rmse, 0.02);  // 3% of a 2 m radius, about 0.06 m
	EXPECT_DOUBLE_EQ(rigid.alignmentScale, 1);
	const auto similar = computeAte(est, gt, {0.5, true, true});
	EXPECT_NEAR(similar.alignmentScale, 1 / 1.03, 1e-9);
	EXPECT_NEAR(similar.rmse, 0, 1e-9);
	EXPECT_NEAR(similar.headingRmse, 0, 1e-9);  // a scale does not turn a heading
	// Without alignment the scale option does nothing.
	EXPECT_DOUBLE_EQ(computeAte(est, gt, {0.5, false, true}).rmse, computeAte(est, gt).rmse);
}

TEST(AbsoluteTrajectoryError, TheSimilarityOfAnUnscaledNoisyEstimateIsNearOne)
{
	// Noise alone should not read as a scale: 0.1 m per axis on a 2 m
	// circle, 5,000 poses; the least-squares scale is biased towards zero
	// by the noise's share of the estimate's spread (0.02 / 4, 0.5%), so
	// the check allows that and no more than a few standard errors
	// (0.1 / (2 sqrt(5000)) = 0.0007) beyond it.
	const auto gt = circle(0, 0.01, 5000);
	auto est = gt;
	mrpt::random::CRandomGenerator rng(5);
	for (auto& p : est)
		p.pose.x += 0.1 * rng.drawGaussian1D_normalized(), p.pose.y += 0.1 * rng.drawGaussian1D_normalized();
	const auto s = computeAte(est, gt, {0.5, true, true});
	EXPECT_NEAR(s.alignmentScale, 1 - 0.02 / 4.02, 0.003);
	EXPECT_LE(s.rmse, computeAte(est, gt, {0.5, true, false}).rmse);  // one more parameter fits no worse
}

TEST(AbsoluteTrajectoryError, NoisyEstimatesHaveTheNoiseLevel)
{
	const auto gt = circle(0, 0.01, 5000);
	auto est = gt;
	mrpt::random::CRandomGenerator rng(3);
	for (auto& p : est)
		p.pose.x += 0.1 * rng.drawGaussian1D_normalized(),
			p.pose.y += 0.1 * rng.drawGaussian1D_normalized();
	const auto s = computeAte(est, gt);
	EXPECT_NEAR(s.rmse, 0.1 * std::sqrt(2.0), 0.005);  // 2-D error
	EXPECT_NEAR(s.mean, 0.1 * std::sqrt(M_PI / 2), 0.005);  // Rayleigh mean
	EXPECT_NEAR(s.median, 0.1 * std::sqrt(2 * std::log(2.0)), 0.005);
}

TEST(AbsoluteTrajectoryError, DifferentSamplingIsInterpolated)
{
	const auto gt = circle(0, 0.1, 200);
	// Estimate sampled at other times: exact poses on the same circle.
	Trajectory est;
	for (int i = 0; i < 60; i++)
	{
		const double t = 0.033 + 0.31 * i;
		const double a = 0.05 * t / 0.1;
		est.push_back({t, {2 * std::cos(a), 2 * std::sin(a), a + M_PI / 2}});
	}
	const auto s = computeAte(est, gt);
	EXPECT_EQ(s.associated, 60u);
	EXPECT_LT(s.max, 2 * 0.05 * 0.05 / 8 * 2 + 1e-3);  // chord error only
}

TEST(AbsoluteTrajectoryError, TimeShiftShowsUpAndOutOfRangePosesAreSkipped)
{
	const auto gt = circle(0, 0.1, 100);
	auto late = gt;
	for (auto& p : late) p.t += 1.0;  // 10 samples late: 0.5 rad along a 2 m circle
	const auto s = computeAte(late, gt);
	EXPECT_EQ(s.associated, 90u);
	EXPECT_NEAR(s.mean, 2 * 2 * std::sin(0.25), 1e-6);
}

TEST(AbsoluteTrajectoryError, GapsInTheGroundTruthAreNotBridged)
{
	auto gt = circle(0, 0.1, 100);
	gt.erase(gt.begin() + 40, gt.begin() + 60);  // a 2 s gap
	const auto s = computeAte(circle(0, 0.1, 100), gt, {0.5, false});
	EXPECT_EQ(s.associated, 80u);
}

TEST(AbsoluteTrajectoryError, GroundTruthWithoutTimesIsMatchedByStep)
{
	// All estimates share one timestamp (as in MRPT's simulated rawlogs):
	// only the step tells them apart.
	Trajectory gt, est;
	for (long i = 0; i < 50; i++)
	{
		gt.push_back({std::nan(""), {0.1 * i, 0, 0}, i});
		est.push_back({1700000000.0, {0.1 * i + (i % 2 ? 0.3 : -0.3), 0, 0}, i});
	}
	est.push_back({1700000000.0, {5, 5, 0}, 99});  // no such ground-truth step
	ASSERT_TRUE(hasOnlySteps(gt));
	const auto s = computeAte(est, gt);
	EXPECT_EQ(s.associated, 50u);
	EXPECT_NEAR(s.rmse, 0.3, 1e-9);
}

#include <gtest/gtest.h>
#include <libvslam/filter/MotionPrior.h>
#include <mrpt/random/RandomGenerators.h>

using namespace vslam;

namespace
{
COdometryAccumulator oneIncrement(const CMotionModel& m, const se2::Pose& u)
{
	COdometryAccumulator acc;
	acc.add(u, m.incrementCovariance(u));
	return acc;
}
}  // namespace

TEST(MotionPrior, DensityIntegratesToOneAndIncludesTheSlipComponent)
{
	CMotionModel::TOptions o;
	o.slip_probability = 0.1;
	const CMotionModel model(o);
	const MotionPrior mp(oneIncrement(model, {0.5, 0, 0.3}), model);
	// Riemann sum over the increment space around the mean.
	const se2::Pose from{1, 2, 0.4};
	double sum = 0;
	const int n = 60;
	const double h = 1.6 / n, hphi = 1.2 / n;
	for (int i = 0; i < n; i++)
		for (int j = 0; j < n; j++)
			for (int k = 0; k < n; k++)
			{
				const se2::Pose d{0.5 - 0.8 + (i + 0.5) * h, -0.8 + (j + 0.5) * h,
								  0.3 - 0.6 + (k + 0.5) * hphi};
				sum += std::exp(mp.logDensity(from, se2::compose(from, d))) * h * h * hphi;
			}
	EXPECT_NEAR(sum, 1.0, 0.02);
	// Far from the mean only the slip component remains.
	const se2::Pose far = se2::compose(from, {0.5, 0.3, 0.3});
	const MotionPrior noSlip(oneIncrement(model, {0.5, 0, 0.3}), [] {
		CMotionModel::TOptions p;
		p.slip_probability = 0;
		return CMotionModel(p);
	}());
	EXPECT_GT(mp.logDensity(from, far), noSlip.logDensity(from, far) + 5);
}

TEST(MotionPrior, SamplesFollowTheMixture)
{
	CMotionModel::TOptions o;
	o.slip_probability = 0.2;
	const CMotionModel model(o);
	const MotionPrior mp(oneIncrement(model, {1.0, 0, 0}), model);
	mrpt::random::CRandomGenerator rng(3);
	const int N = 100000;
	double var = 0;
	for (int i = 0; i < N; i++)
	{
		const se2::Pose s = mp.sample(rng, {0, 0, 0});
		var += s.y * s.y;
	}
	var /= N;
	// Mixture variance of the lateral error: (1-e) a + e (a + slip^2).
	const double a = mp.cov()(1, 1);
	const double expected = a + o.slip_probability * o.slip_std_xy * o.slip_std_xy;
	EXPECT_NEAR(var, expected, 0.03 * expected);
}

#include <gtest/gtest.h>
#include <libvslam/models/CMotionModel.h>
#include <libvslam/models/COdometryAccumulator.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>

using namespace vslam;

TEST(COdometryAccumulator, ComposesMeans)
{
	COdometryAccumulator acc;
	EXPECT_TRUE(acc.empty());
	mrpt::poses::CPose2D ref;
	for (int i = 0; i < 20; i++)
	{
		const se2::Pose u{0.1, 0.01 * i, 0.05 * (i % 3 - 1)};
		acc.add(u, Eigen::Matrix3d::Zero());
		ref = ref + mrpt::poses::CPose2D(u);
	}
	EXPECT_FALSE(acc.empty());
	EXPECT_NEAR(acc.mean().x, ref.x(), 1e-12);
	EXPECT_NEAR(acc.mean().y, ref.y(), 1e-12);
	EXPECT_NEAR(acc.mean().phi, ref.phi(), 1e-12);
	acc.reset();
	EXPECT_TRUE(acc.empty());
	EXPECT_EQ(acc.mean().x, 0.0);
}

TEST(COdometryAccumulator, CovarianceMatchesMonteCarlo)
{
	// An out-and-back path: the accumulated covariance must keep the noise
	// of the whole trip although the net displacement is small.
	CMotionModel::TOptions o;
	o.sigma_T = 0.05;
	o.sigma_R = 0.05;
	o.sigma_R_per_meter = 0.02;
	const CMotionModel model(o);
	std::vector<se2::Pose> incs;
	for (int i = 0; i < 10; i++) incs.push_back({0.1, 0, 0});
	for (int i = 0; i < 10; i++) incs.push_back({0, 0, M_PI / 10});
	for (int i = 0; i < 10; i++) incs.push_back({0.1, 0, 0});

	COdometryAccumulator acc;
	for (const auto& u : incs) acc.add(u, model.incrementCovariance(u));

	mrpt::random::CRandomGenerator rng(7);
	const int N = 20000;
	std::vector<Eigen::Vector3d> samples;
	Eigen::Vector3d mean = Eigen::Vector3d::Zero();
	for (int k = 0; k < N; k++)
	{
		se2::Pose p{0, 0, 0};
		for (const auto& u : incs)
		{
			const Eigen::Matrix3d C = model.incrementCovariance(u);
			const se2::Pose noisy{
				u.x + std::sqrt(C(0, 0)) * rng.drawGaussian1D_normalized(),
				u.y + std::sqrt(C(1, 1)) * rng.drawGaussian1D_normalized(),
				u.phi + std::sqrt(C(2, 2)) * rng.drawGaussian1D_normalized()};
			p = se2::compose(p, noisy);
		}
		// Deviation in the frame where the increment starts (= origin).
		samples.push_back(se2::difference(p, acc.mean()));
		mean += samples.back();
	}
	mean /= N;
	Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
	for (const auto& s : samples) cov += (s - mean) * (s - mean).transpose();
	cov /= N - 1;
	// The whole trip's noise is kept (2 m travelled), not the net motion's.
	EXPECT_GT(acc.cov()(0, 0), 0.9 * o.sigma_T * o.sigma_T * 2.0);
	for (int r = 0; r < 3; r++)
		for (int c = 0; c < 3; c++)
			EXPECT_NEAR(cov(r, c), acc.cov()(r, c), 0.06 * acc.cov().norm())
				<< r << "," << c;
}

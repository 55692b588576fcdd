/** The odometry error model draws errors with the configured statistics. */
#include <gtest/gtest.h>
#include <libvslam/sim/OdometryErrorModel.h>

#include <cmath>

using namespace vslam;

TEST(OdometryErrorModel, ErrorsHaveTheConfiguredMeanAndSpread)
{
	TOdometryErrorModel m;
	m.sigma_T = 0.05, m.sigma_R = 0.05, m.sigma_R_per_meter = 0.02;
	m.scale_bias = 0.02, m.turn_bias = -0.03;
	mrpt::random::CRandomGenerator rng(3);
	const se2::Pose u{0.04, 0, 0.02};  // 4 cm forward, 1.15 deg turn
	const int N = 200000;
	double sx = 0, sxx = 0, sy = 0, syy = 0, sp = 0, spp = 0;
	for (int i = 0; i < N; i++)
	{
		const se2::Pose z = m.measured(u, rng);
		sx += z.x, sxx += z.x * z.x, sy += z.y, syy += z.y * z.y, sp += z.phi, spp += z.phi * z.phi;
	}
	const auto stddev = [&](double s, double ss) { return std::sqrt(ss / N - (s / N) * (s / N)); };
	const double sT = 0.05 * std::sqrt(0.04);
	const double sR = std::sqrt(0.05 * 0.05 * 0.02 + 0.02 * 0.02 * 0.04);
	EXPECT_NEAR(sx / N, 0.04 * 1.02, 4 * sT / std::sqrt(N));
	EXPECT_NEAR(sy / N, 0.0, 4 * sT / std::sqrt(N));
	EXPECT_NEAR(sp / N, 0.02 * 0.97, 4 * sR / std::sqrt(N));
	EXPECT_NEAR(stddev(sx, sxx), sT, 0.01 * sT);
	EXPECT_NEAR(stddev(sy, syy), sT, 0.01 * sT);
	EXPECT_NEAR(stddev(sp, spp), sR, 0.01 * sR);
}

TEST(OdometryErrorModel, SlipsHappenAtTheConfiguredRate)
{
	TOdometryErrorModel m;
	m.slip_probability = 0.01, m.slip_std = 0.05;
	mrpt::random::CRandomGenerator rng(4);
	int slips = 0;
	double s2 = 0;
	for (int i = 0; i < 100000; i++)
		if (se2::Pose s; m.slip(rng, s)) slips++, s2 += s.x * s.x + s.y * s.y;
	EXPECT_NEAR(slips, 1000, 4 * std::sqrt(1000.0));
	EXPECT_NEAR(std::sqrt(s2 / (2 * slips)), 0.05, 0.005);
	m.slip_probability = 0;
	se2::Pose s;
	EXPECT_FALSE(m.slip(rng, s));
}

#include <gtest/gtest.h>
#include <libvslam/config/ConfigError.h>
#include <libvslam/config/IniText.h>
#include <libvslam/models/CMotionModel.h>
#include <mrpt/config/CConfigFileMemory.h>

using namespace vslam;

TEST(CMotionModel, CovarianceFollowsTheDocumentedModel)
{
	CMotionModel::TOptions o;
	o.sigma_T = 0.1;
	o.sigma_R = 0.2;
	o.sigma_R_per_meter = 0.05;
	const CMotionModel m(o);
	const Eigen::Matrix3d C = m.incrementCovariance({0.3, 0.4, -0.5});
	EXPECT_NEAR(C(0, 0), 0.01 * 0.5, 1e-15);
	EXPECT_NEAR(C(1, 1), 0.01 * 0.5, 1e-15);
	EXPECT_NEAR(C(2, 2), 0.04 * 0.5 + 0.0025 * 0.5, 1e-15);
	EXPECT_EQ(C(0, 1), 0.0);
	EXPECT_TRUE(m.incrementCovariance({0, 0, 0}).isZero());
}

TEST(CMotionModel, SplittingAnIncrementKeepsTheTotalVariance)
{
	const CMotionModel m;
	const double total = m.incrementCovariance({1.0, 0, 0})(0, 0);
	double sum = 0;
	for (int i = 0; i < 10; i++) sum += m.incrementCovariance({0.1, 0, 0})(0, 0);
	EXPECT_NEAR(sum, total, 1e-15);
}

TEST(CMotionModel, OptionsRoundTripAndRangeChecks)
{
	CMotionModel::TOptions o;
	o.sigma_T = 0.07;
	o.slip_std_phi = 0.2;
	const auto cfg = config::toParsedConfig(o, "m");
	CMotionModel::TOptions back;
	back.loadFromConfigFile(cfg, "m");
	EXPECT_NEAR(back.sigma_T, 0.07, 1e-6);
	EXPECT_NEAR(back.slip_std_phi, 0.2, 1e-6);

	mrpt::config::CConfigFileMemory bad("[m]\nsigma_T = -1\n");
	EXPECT_THROW(back.loadFromConfigFile(bad, "m"), ConfigError);
	mrpt::config::CConfigFileMemory nan("[m]\nsigma_R = abc\n");
	EXPECT_THROW(back.loadFromConfigFile(nan, "m"), ConfigError);
}

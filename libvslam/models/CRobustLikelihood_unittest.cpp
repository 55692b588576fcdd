#include <gtest/gtest.h>
#include <libvslam/config/ConfigError.h>
#include <libvslam/models/CRobustLikelihood.h>
#include <mrpt/config/CConfigFileMemory.h>

using namespace vslam;

namespace
{
MeasurementEvaluation evalWithNis(double nis, int dim)
{
	MeasurementEvaluation e;
	e.innovation = VecN::Zero(dim);
	e.innovation[0] = std::sqrt(nis);
	e.S = MatN::Identity(dim, dim);
	e.gaussian = evaluateGaussian(e.innovation, e.S);
	return e;
}
}  // namespace

TEST(CRobustLikelihood, GaussianNearTheCenterUniformFloorFarAway)
{
	CRobustLikelihood::TOptions o;
	o.outlier_probability = 0.1;
	o.outlier_max_range = 5;
	const CRobustLikelihood lik(o);
	const auto near = evalWithNis(0.0, 3);
	EXPECT_NEAR(
		lik.logLikelihood(near, LandmarkKind::Pose),
		std::log(0.9 * std::exp(near.gaussian.logDensity) +
				 0.1 / (100.0 * 2 * M_PI)),
		1e-12);
	const double floorPose = std::log(0.1 / (100.0 * 2 * M_PI));
	EXPECT_NEAR(
		lik.logLikelihood(evalWithNis(1e4, 3), LandmarkKind::Pose), floorPose,
		1e-9);
	EXPECT_NEAR(
		lik.logLikelihood(evalWithNis(1e4, 2), LandmarkKind::Point),
		std::log(0.1 / (5.0 * 2 * M_PI)), 1e-9);
}

TEST(CRobustLikelihood, GateUsesExactChiSquareQuantiles)
{
	CRobustLikelihood::TOptions o;
	o.gate_probability = 0.95;
	const CRobustLikelihood lik(o);
	EXPECT_NEAR(lik.gate(2), 5.991465, 1e-5);
	EXPECT_TRUE(lik.inGate(evalWithNis(5.9, 2)));
	EXPECT_FALSE(lik.inGate(evalWithNis(6.0, 2)));
	EXPECT_TRUE(lik.inGate(evalWithNis(7.8, 3)));
}

TEST(CRobustLikelihood, OptionRangesAreChecked)
{
	CRobustLikelihood::TOptions o;
	mrpt::config::CConfigFileMemory bad("[l]\noutlier_probability = 1.0\n");
	EXPECT_THROW(o.loadFromConfigFile(bad, "l"), ConfigError);
	mrpt::config::CConfigFileMemory bad2("[l]\ngate_probability = 0\n");
	EXPECT_THROW(o.loadFromConfigFile(bad2, "l"), ConfigError);
}

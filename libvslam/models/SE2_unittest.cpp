#include <gtest/gtest.h>
#include <libvslam/models/SE2.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>
#include <tests/support/NumericalDerivative.h>

using namespace vslam;
using vslam::testing::numericalJacobian;
using vslam::testing::poseVec;
using vslam::testing::vecPose;

namespace
{
se2::Pose randomPose(mrpt::random::CRandomGenerator& rng)
{
	return {rng.drawUniform(-5, 5), rng.drawUniform(-5, 5),
			rng.drawUniform(-M_PI, M_PI)};
}

void expectPoseNear(const se2::Pose& a, const se2::Pose& b, double tol = 1e-9)
{
	EXPECT_NEAR(a.x, b.x, tol);
	EXPECT_NEAR(a.y, b.y, tol);
	EXPECT_NEAR(se2::wrap(a.phi - b.phi), 0.0, tol);
}
}  // namespace

TEST(SE2, AgreesWithMrptPoseAlgebra)
{
	mrpt::random::CRandomGenerator rng(1);
	for (int i = 0; i < 100; i++)
	{
		const se2::Pose a = randomPose(rng), b = randomPose(rng);
		const mrpt::poses::CPose2D A(a), B(b);
		expectPoseNear(se2::compose(a, b), (A + B).asTPose());
		expectPoseNear(se2::between(a, b), (B - A).asTPose());
		expectPoseNear(se2::inverse(a), (-A).asTPose());
		expectPoseNear(se2::between(a, se2::compose(a, b)), b);
	}
}

TEST(SE2, JacobiansMatchNumericalDerivatives)
{
	mrpt::random::CRandomGenerator rng(2);
	for (int i = 0; i < 50; i++)
	{
		const se2::Pose a = randomPose(rng), b = randomPose(rng);
		const auto composeA = [&](const Eigen::VectorXd& x) {
			return poseVec(se2::compose(vecPose(x), b));
		};
		const auto composeB = [&](const Eigen::VectorXd& x) {
			return poseVec(se2::compose(a, vecPose(x)));
		};
		const auto betweenA = [&](const Eigen::VectorXd& x) {
			return poseVec(se2::between(vecPose(x), b));
		};
		const auto betweenB = [&](const Eigen::VectorXd& x) {
			return poseVec(se2::between(a, vecPose(x)));
		};
		const auto inv = [&](const Eigen::VectorXd& x) {
			return poseVec(se2::inverse(vecPose(x)));
		};
		const double tol = 1e-6;
		EXPECT_TRUE(se2::jacComposeA(a, b).isApprox(
			numericalJacobian(composeA, poseVec(a), {2}), tol));
		EXPECT_TRUE(se2::jacComposeB(a, b).isApprox(
			numericalJacobian(composeB, poseVec(b), {2}), tol));
		EXPECT_TRUE(se2::jacBetweenA(a, b).isApprox(
			numericalJacobian(betweenA, poseVec(a), {2}), tol));
		EXPECT_TRUE(se2::jacBetweenB(a, b).isApprox(
			numericalJacobian(betweenB, poseVec(b), {2}), tol));
		EXPECT_TRUE(se2::jacInverse(a).isApprox(
			numericalJacobian(inv, poseVec(a), {2}), tol));
	}
}

TEST(SE2, DifferenceWrapsTheAngle)
{
	const Eigen::Vector3d d =
		se2::difference({1, 2, M_PI - 0.1}, {0, 0, -M_PI + 0.1});
	EXPECT_NEAR(d[2], -0.2, 1e-12);
}

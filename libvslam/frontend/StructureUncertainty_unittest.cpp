/** The point and pose uncertainty of StructureUncertainty.h: the analytic
 * Jacobian against a numerical one, the depth std of a stereo pair against
 * its closed form, the pose covariance against a Monte Carlo scatter. */
#include <gtest/gtest.h>
#include <libvslam/frontend/StructureUncertainty.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <opencv2/calib3d.hpp>

#include <cmath>
#include <random>

using namespace vslam;

namespace
{
constexpr double kF = 250;

Eigen::Vector2d project(const Eigen::Matrix3d& R, const Eigen::Vector3d& t, const Eigen::Vector3d& X)
{
	const Eigen::Vector3d c = R * X + t;
	return {kF * c.x() / c.z(), kF * c.y() / c.z()};
}
}  // namespace

TEST(StructureUncertainty, ProjectionJacobianWrtPointMatchesTheNumericalDerivative)
{
	const Eigen::Matrix3d R = (Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.2, 1, -0.1).normalized())).toRotationMatrix();
	const Eigen::Vector3d t(0.1, -0.2, 0.5);
	const Eigen::Vector3d X(0.4, 0.3, 2.5);
	const Eigen::Matrix<double, 2, 3> J = projectionJacobianWrtPoint(R, t, kF, kF, X);
	for (int k = 0; k < 3; k++)
	{
		constexpr double h = 1e-6;
		const Eigen::Vector3d d = h * Eigen::Vector3d::Unit(k);
		const Eigen::Vector2d numerical = (project(R, t, X + d) - project(R, t, X - d)) / (2 * h);
		EXPECT_NEAR((J.col(k) - numerical).norm(), 0, 1e-6 * numerical.norm() + 1e-6) << "column " << k;
	}
}

TEST(StructureUncertainty, DepthStdOfAStereoPairIsPixelNoiseOverDisparity)
{
	// Cameras at x = -b/2 and +b/2, a point straight ahead at depth d:
	// sigma_z = sqrt(2) sigma d^2 / (f b).
	const double b = 0.2, d = 2.0, sigma = 0.7;
	const Eigen::Vector3d X(0, 0, d);
	std::vector<Eigen::Matrix<double, 2, 3>> J;
	for (double cx : {-b / 2, b / 2})
		J.push_back(projectionJacobianWrtPoint(Eigen::Matrix3d::Identity(), Eigen::Vector3d(-cx, 0, 0), kF, kF, X));
	EXPECT_NEAR(stdAlongDirection(J, Eigen::Vector3d::UnitZ(), sigma), std::sqrt(2.0) * sigma * d * d / (kF * b), 1e-9);
	// Across the ray it is known as well as pixel noise allows.
	EXPECT_NEAR(stdAlongDirection(J, Eigen::Vector3d::UnitX(), sigma), sigma * d / kF / std::sqrt(2.0), 1e-9);
	// One view alone does not constrain the depth.
	EXPECT_TRUE(std::isinf(stdAlongDirection({J[0]}, Eigen::Vector3d::UnitZ(), sigma)));
}

namespace
{
/** Residuals of `points` for the pose (rvec, tvec), each point's depth std
 * `depthStd` of its distance from the origin (the camera that built it). */
std::vector<PoseSolveResidual> residualsOf(
	const std::vector<cv::Point3d>& points, const cv::Mat& rvec, const cv::Mat& tvec, const cv::Matx33d& K, double depthStd)
{
	const std::vector<cv::Point3f> asFloat(points.begin(), points.end());
	return poseSolveResiduals(asFloat, std::vector<float>(points.size(), static_cast<float>(depthStd)),
		Eigen::Vector3d::Zero(), rvec, tvec, K);
}
}  // namespace

TEST(StructureUncertainty, PoseCovarianceMatchesTheScatterOfPosesFitToUncertainPoints)
{
	// 40 points 2-4 m in front of the camera that built them, each off
	// along its ray by 3% of its distance (a short baseline), seen from
	// 1 m to the side and turned 25 deg towards them, with 0.5 px noise.
	// (The covariance is first order: at 10% the scatter's tails are
	// heavier than it says, a mean NEES of 11.6 instead of 6.)
	std::mt19937 rng(5);
	std::uniform_real_distribution<double> u(-1, 1);
	std::normal_distribution<double> g;
	std::vector<cv::Point3d> truth;
	for (int i = 0; i < 40; i++) truth.emplace_back(1.2 * u(rng), 0.5 * u(rng), 3 + u(rng));
	const cv::Matx33d K(kF, 0, 320, 0, kF, 240, 0, 0, 1);
	const cv::Mat rvec = (cv::Mat_<double>(3, 1) << 0, 25 * M_PI / 180, 0);
	cv::Mat Rcv;
	cv::Rodrigues(rvec, Rcv);
	const cv::Mat tvec = -Rcv * (cv::Mat_<double>(3, 1) << 1.0, 0, 0.3);
	const double depthStd = 0.03, sigmaPx = 0.5;
	std::vector<cv::Point2d> exact;
	cv::projectPoints(truth, rvec, tvec, cv::Mat(K), cv::noArray(), exact);

	Eigen::Matrix<double, 6, 6> withStructure, pixelsOnly;
	ASSERT_TRUE(poseCovariance(residualsOf(truth, rvec, tvec, K, depthStd), sigmaPx, withStructure));
	ASSERT_TRUE(poseCovariance(residualsOf(truth, rvec, tvec, K, 0), sigmaPx, pixelsOnly));
	const Eigen::Matrix<double, 6, 6> information = withStructure.inverse();

	const int trials = 400;
	double nees = 0, neesPixelsOnly = 0;
	for (int k = 0; k < trials; k++)
	{
		std::vector<cv::Point3d> built;
		for (const auto& p : truth) built.push_back(p * (1 + depthStd * g(rng)));  // along the ray from the origin
		std::vector<cv::Point2d> seen;
		for (const auto& px : exact) seen.emplace_back(px.x + sigmaPx * g(rng), px.y + sigmaPx * g(rng));
		cv::Mat r = rvec.clone(), t = tvec.clone();
		cv::solvePnP(built, seen, cv::Mat(K), cv::noArray(), r, t, true, cv::SOLVEPNP_ITERATIVE);
		Eigen::Matrix<double, 6, 1> e;
		for (int i = 0; i < 3; i++) e(i) = r.at<double>(i) - rvec.at<double>(i), e(3 + i) = t.at<double>(i) - tvec.at<double>(i);
		nees += e.dot(information * e) / trials;
		neesPixelsOnly += e.dot(pixelsOnly.inverse() * e) / trials;
	}
	// A consistent 6-D covariance gives a mean NEES of 6 (400 trials: +-0.2;
	// 6.6 measured).
	EXPECT_GT(nees, 6 * 0.8);
	EXPECT_LT(nees, 6 * 1.25);
	// The pixel noise alone explains a fraction of the scatter.
	EXPECT_GT(neesPixelsOnly, 3 * 6);
	// Without structure the formula is the plain sigma^2 (J^T J)^-1.
	Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
	for (const auto& r : residualsOf(truth, rvec, tvec, K, 0)) A += r.jacobianWrtPose.transpose() * r.jacobianWrtPose;
	EXPECT_LT((pixelsOnly - sigmaPx * sigmaPx * A.inverse()).norm(), 1e-9 * pixelsOnly.norm());
}

TEST(StructureUncertainty, TooFewResidualsForAPoseAreReportedNotInverted)
{
	std::vector<PoseSolveResidual> two(2);
	two[0].jacobianWrtPose.setRandom();
	two[1].jacobianWrtPose.setRandom();
	Eigen::Matrix<double, 6, 6> cov = Eigen::Matrix<double, 6, 6>::Constant(7);
	EXPECT_FALSE(poseCovariance(two, 0.5, cov));
	EXPECT_EQ(cov(0, 0), 7);
}

#include <gtest/gtest.h>
#include <libvslam/frontend/PlanarPose.h>
#include <tests/support/NumericalDerivative.h>

#include <random>

using namespace vslam;

namespace
{
constexpr double kDeg = M_PI / 180;
// A forward-looking camera 0.3 m up, 0.1 m ahead of the robot centre,
// tilted 5 deg up (x right, y down, z forward in the camera).
const mrpt::poses::CPose3D kMount(0.1, 0, 0.3, -90 * kDeg, 0, -95 * kDeg);
const cv::Matx33d kK(256, 0, 160, 0, 256, 120, 0, 0, 1);

/** Points on and before a wall about 3 m ahead of the landmark frame. */
std::vector<cv::Point3f> wallPoints(int n, std::mt19937& rng)
{
	std::uniform_real_distribution<float> across(-1.5f, 1.5f), up(0.0f, 1.5f), depth(2.5f, 3.5f);
	std::vector<cv::Point3f> p;
	for (int i = 0; i < n; i++) p.emplace_back(depth(rng), across(rng), up(rng));
	return p;
}

std::vector<cv::Point2f> pixelsFrom(const mrpt::poses::CPose3D& camera, const std::vector<cv::Point3f>& points)
{
	std::vector<cv::Point2f> px;
	for (const auto& P : points)
	{
		double x, y, z;
		camera.inverseComposePoint(P.x, P.y, P.z, x, y, z);
		px.emplace_back(static_cast<float>(kK(0, 0) * x / z + kK(0, 2)), static_cast<float>(kK(1, 1) * y / z + kK(1, 2)));
	}
	return px;
}
}  // namespace

TEST(PlanarPose, ProjectionMatchesTheMountedCameraAndItsJacobianTheNumericalOne)
{
	std::mt19937 rng(3);
	const PlanarCameraState r{{0.4, -0.2, 12 * kDeg}, 0.03};
	const auto points = wallPoints(20, rng);
	const auto expected =
		pixelsFrom(mrpt::poses::CPose3D(r.robot.x, r.robot.y, r.height, r.robot.phi, 0, 0) + kMount, points);
	for (size_t i = 0; i < points.size(); i++)
	{
		const Eigen::Vector3d P(points[i].x, points[i].y, points[i].z);
		Eigen::Vector2d pixel;
		Eigen::Matrix<double, 2, 4> J;
		ASSERT_TRUE(projectPlanar(r, P, kMount, kK, pixel, &J));
		EXPECT_NEAR(pixel.x(), expected[i].x, 1e-3);
		EXPECT_NEAR(pixel.y(), expected[i].y, 1e-3);
		const Eigen::MatrixXd numerical = vslam::testing::numericalJacobian(
			[&](const Eigen::VectorXd& v) {
				Eigen::Vector2d q;
				projectPlanar({{v[0], v[1], v[2]}, v[3]}, P, kMount, kK, q);
				return Eigen::VectorXd(q);
			},
			Eigen::Vector4d(r.robot.x, r.robot.y, r.robot.phi, r.height));
		EXPECT_LT((numerical - J).cwiseAbs().maxCoeff(), 1e-4) << "point " << i << "\n" << J << "\n" << numerical;
	}
	// Behind the camera: no pixel.
	Eigen::Vector2d pixel;
	EXPECT_FALSE(projectPlanar(r, Eigen::Vector3d(-3, 0, 0.5), kMount, kK, pixel));
}

TEST(PlanarPose, ConvergesToTheTruePoseAndDropsOutliers)
{
	std::mt19937 rng(5);
	const se2::Pose truth{0.6, 0.3, -8 * kDeg};
	auto points = wallPoints(60, rng);
	auto pixels = pixelsFrom(mrpt::poses::CPose3D(truth.x, truth.y, 0, truth.phi, 0, 0) + kMount, points);
	std::normal_distribution<float> noise(0, 0.5f);
	for (auto& p : pixels) p += cv::Point2f(noise(rng), noise(rng));
	for (int i = 0; i < 10; i++) pixels[i] += cv::Point2f(40, -25);  // wrong matches
	// Started off the truth, from the points a 6-DOF solve kept.
	std::vector<int> kept;
	for (int i = 10; i < 60; i++) kept.push_back(i);
	const PlanarPoseFit fit = refinePlanarPose(
		{{truth.x + 0.08, truth.y - 0.06, truth.phi + 3 * kDeg}, 0.02}, kept, points, pixels, kMount, kK, 3.0);
	EXPECT_NEAR(fit.state.robot.x, truth.x, 0.02);
	EXPECT_NEAR(fit.state.robot.y, truth.y, 0.02);
	EXPECT_NEAR(fit.state.robot.phi, truth.phi, 0.2 * kDeg);
	EXPECT_NEAR(fit.state.height, 0, 0.01);
	EXPECT_EQ(fit.inliers.size(), 50u);
	EXPECT_EQ(fit.inliers.front(), 10);
	EXPECT_LT(fit.rmsPx, 1.0);
	// The predicted std covers the error actually made, and is small.
	EXPECT_GT(fit.covariance(0, 0), 0);
	EXPECT_LT(std::sqrt(fit.covariance(2, 2)), 0.5 * kDeg);
}

TEST(PlanarPose, ALandmarkWithAScaleErrorGivesTheScaledPoseAndTheHeightTakesItUp)
{
	// The landmark's points (and so its frame's lengths) are 10% too large:
	// the camera's true pose, scaled by 1.1, explains the pixels exactly,
	// with the camera 1.1 times the mount's height above the floor.
	std::mt19937 rng(9);
	const se2::Pose truth{0.6, 0.3, -8 * kDeg};
	const auto points = wallPoints(60, rng);
	const auto pixels = pixelsFrom(mrpt::poses::CPose3D(truth.x, truth.y, 0, truth.phi, 0, 0) + kMount, points);
	constexpr double s = 1.1;
	std::vector<cv::Point3f> scaled;
	for (const auto& p : points) scaled.push_back(p * s);
	std::vector<int> all(points.size());
	for (size_t i = 0; i < all.size(); i++) all[i] = static_cast<int>(i);
	const PlanarPoseFit fit = refinePlanarPose({truth, 0}, all, scaled, pixels, kMount, kK, 3.0);
	EXPECT_EQ(fit.inliers.size(), points.size());
	EXPECT_NEAR(fit.state.robot.phi, truth.phi, 0.01 * kDeg);
	// The robot's frame origin (below the camera) is where the scaled
	// camera's mount places it.
	const mrpt::poses::CPose3D camera = mrpt::poses::CPose3D(truth.x, truth.y, 0, truth.phi, 0, 0) + kMount;
	const mrpt::poses::CPose3D fitted =
		mrpt::poses::CPose3D(fit.state.robot.x, fit.state.robot.y, fit.state.height, fit.state.robot.phi, 0, 0) +
		kMount;
	EXPECT_NEAR(fitted.x(), s * camera.x(), 1e-3);
	EXPECT_NEAR(fitted.y(), s * camera.y(), 1e-3);
	EXPECT_NEAR(fitted.z(), s * camera.z(), 1e-3);
	EXPECT_LT(fit.rmsPx, 1e-3);
}

TEST(PlanarPose, AViewOnlyATiltedCameraExplainsKeepsFewInliers)
{
	// The pixels come from a camera rolled and pitched 8 deg: a 6-DOF solve
	// fits them exactly, the planar model cannot, so few points stay within
	// the inlier threshold.
	std::mt19937 rng(7);
	const auto points = wallPoints(60, rng);
	const mrpt::poses::CPose3D tiltedRobot(0.5, 0.2, 0, 5 * kDeg, 8 * kDeg, 8 * kDeg);
	const auto pixels = pixelsFrom(tiltedRobot + kMount, points);
	std::vector<int> all(points.size());
	for (size_t i = 0; i < all.size(); i++) all[i] = static_cast<int>(i);
	const PlanarPoseFit fit = refinePlanarPose({{0.5, 0.2, 5 * kDeg}, 0}, all, points, pixels, kMount, kK, 3.0);
	EXPECT_LT(fit.inliers.size(), 12u);
	// The same from an upright robot: all inliers.
	const auto upright = pixelsFrom(mrpt::poses::CPose3D(0.5, 0.2, 0, 5 * kDeg, 0, 0) + kMount, points);
	EXPECT_EQ(refinePlanarPose({{0.5, 0.2, 5 * kDeg}, 0}, all, points, upright, kMount, kK, 3.0).inliers.size(), 60u);
}

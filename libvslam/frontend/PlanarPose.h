#pragma once
/** \file PlanarPose.h
 * The camera pose relative to a landmark's 3-D points when the robot moves
 * on the floor plane: the robot's planar pose (x, y, theta) in the landmark
 * frame (itself a robot pose at creation, so on the same plane), with the
 * camera's tilt fixed by its mount. A 6-DOF solve can explain a few matches
 * with a tilted camera that the robot cannot have; the planar model cannot.
 *
 * The height is left free: a landmark's points carry its scale error (the
 * scale comes from an odometry baseline), and in a frame scaled by s the
 * camera sits at s times its mount height. A fixed height would turn that
 * into errors of (x, y, theta); a free one takes it up (height / mount
 * height is the landmark's scale error, to first order).
 *
 * Levenberg-Marquardt on the pixel reprojection error of the given points,
 * with the analytic Jacobian of projectPlanar(). The pixels are undistorted
 * (the pinhole K alone maps camera rays to them).
 */
#include <libvslam/models/SE2.h>
#include <mrpt/poses/CPose3D.h>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <vector>

namespace vslam
{
/** Robot pose in the landmark frame, and how far the camera sits above
 * (positive) or below its mount height there (m, in the landmark's units). */
struct PlanarCameraState
{
	se2::Pose robot;
	double height = 0;
};

/** The pixel of landmark point P seen from `s` through the camera mount;
 * with its 2x4 Jacobian in (x, y, theta, height) if J is given. False if
 * the point is not in front of the camera. */
bool projectPlanar(const PlanarCameraState& s, const Eigen::Vector3d& P, const mrpt::poses::CPose3D& mount,
	const cv::Matx33d& K, Eigen::Vector2d& pixel, Eigen::Matrix<double, 2, 4>* J = nullptr);

struct PlanarPoseFit
{
	PlanarCameraState state;
	/** The inliers of the final pose (squared error within the threshold). */
	std::vector<int> inliers;
	double rmsPx = 0;  //!< over the inliers
	/** Covariance of (x, y, theta), the height marginalized: sigma^2 times
	 * the inverse information over the inliers, sigma the per-coordinate
	 * pixel noise their residuals imply (at least 0.35 px); infinite if
	 * singular. */
	Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
};

/** Refines `initial` on the points `initialInliers` (e.g. a 6-DOF solve's
 * inliers): Levenberg-Marquardt on those, then the inliers again (within
 * `inlierPx` of their projection) from the new pose, a few rounds until
 * they stop changing. */
PlanarPoseFit refinePlanarPose(const PlanarCameraState& initial, const std::vector<int>& initialInliers,
	const std::vector<cv::Point3f>& points, const std::vector<cv::Point2f>& pixels,
	const mrpt::poses::CPose3D& mount, const cv::Matx33d& K, double inlierPx);
}  // namespace vslam

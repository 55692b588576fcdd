#pragma once
/** \file PlanarPose.h
 * The camera pose relative to a landmark's 3-D points when the robot moves
 * on the floor plane: the robot's planar pose (x, y, theta) in the landmark
 * frame (itself a robot pose at creation, so on the same plane), with the
 * camera mount fixed. Three unknowns instead of PnP's six: a 6-DOF solve can
 * explain a few matches with a tilted camera that the robot cannot have (the
 * mirror solution of near-planar point sets seen from afar is one), the
 * planar model cannot.
 *
 * Levenberg-Marquardt on the pixel reprojection error of the given points, with the
 * analytic Jacobian of projectPlanar(). The pixels are undistorted (the
 * pinhole K alone maps camera rays to them).
 */
#include <libvslam/models/SE2.h>
#include <mrpt/poses/CPose3D.h>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <vector>

namespace vslam
{
/** The pixel of landmark point P seen from robot pose r (in the landmark
 * frame) through the camera mount; with its 2x3 Jacobian in (x, y, theta)
 * if J is given. False if the point is not in front of the camera. */
bool projectPlanar(const se2::Pose& r, const Eigen::Vector3d& P, const mrpt::poses::CPose3D& mount,
	const cv::Matx33d& K, Eigen::Vector2d& pixel, Eigen::Matrix<double, 2, 3>* J = nullptr);

struct PlanarPoseFit
{
	se2::Pose robotInLandmark;
	/** The inliers of the final pose (squared error within the threshold). */
	std::vector<int> inliers;
	double rmsPx = 0;  //!< over the inliers
	/** Covariance of (x, y, theta): sigma^2 (J^T J)^-1 over the inliers,
	 * sigma their RMS error (at least 0.5 px); infinite if singular. */
	Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
};

/** Refines `initial` on the points `initialInliers` (e.g. a 6-DOF solve's
 * inliers): Levenberg-Marquardt on those, then the inliers again (within
 * `inlierPx` of their projection) from the new pose, a few rounds until
 * they stop changing. */
PlanarPoseFit refinePlanarPose(const se2::Pose& initial, const std::vector<int>& initialInliers,
	const std::vector<cv::Point3f>& points, const std::vector<cv::Point2f>& pixels,
	const mrpt::poses::CPose3D& mount, const cv::Matx33d& K, double inlierPx);
}  // namespace vslam

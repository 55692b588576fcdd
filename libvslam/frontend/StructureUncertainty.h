#pragma once
/** \file StructureUncertainty.h
 * How uncertain a landmark's 3-D points are, and what that does to a pose
 * solved from them.
 *
 * A point triangulated from a short baseline is known well across its ray
 * and poorly along it: its depth std is pixel noise over parallax. From the
 * view it was built from, a depth error does not move its projection; from
 * the side it does, and a PnP pose fit to such points is off by more than
 * the reprojection error says. The landmark keeps one number per point, its
 * std along the ray from the creation camera relative to its distance
 * (scale-free, so it survives the scale track's rescaling), and the
 * recognition adds that to each inlier's pixel noise when it predicts the
 * measurement's covariance.
 */
#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <vector>

namespace vslam
{
/** The least pixel noise a fit is credited with: a fit's own RMS error
 * below it is luck with few points, not precision. */
constexpr double kLeastPixelNoisePx = 0.5;

/** Jacobian of the pinhole projection of X (object frame) for the pose
 * X_cam = R X + t, with respect to X (2 x 3, pixels per metre). */
Eigen::Matrix<double, 2, 3> projectionJacobianWrtPoint(
	const Eigen::Matrix3d& R, const Eigen::Vector3d& t, double fx, double fy, const Eigen::Vector3d& X);

/** The std of a triangulated point along the unit vector `direction`, from
 * the Jacobians of its reprojections with respect to the point (cameras
 * held fixed) and the pixel noise `sigmaPx`: sqrt(u^T sigma^2 (sum J^T J)^-1
 * u). Infinite when the views do not constrain the point. */
double stdAlongDirection(
	const std::vector<Eigen::Matrix<double, 2, 3>>& jacobians, const Eigen::Vector3d& direction, double sigmaPx);

/** One inlier of a pose solve: its Jacobian with respect to the pose (the
 * solve's 6 parameters) and its extra pixel covariance from the point's own
 * uncertainty (J_X C_X J_X^T; zero for an exact point). */
struct PoseSolveResidual
{
	Eigen::Matrix<double, 2, 6> jacobianWrtPose;
	Eigen::Matrix2d structureCovariancePx = Eigen::Matrix2d::Zero();
	Eigen::Vector2d projectedPx = Eigen::Vector2d::Zero();  //!< where the pose projects the point
};

/** The residuals of a PnP pose X_cam = R(rvec) X + tvec (OpenCV's
 * parametrization, camera matrix K, no distortion) over `points`: their
 * Jacobians with respect to (rvec, tvec), and the pixel covariance of each
 * point's std along its ray from `rayOrigin` (the camera that built it),
 * `relativeDepthStd[k]` times its distance from there. An empty
 * `relativeDepthStd` takes the points as exact. */
std::vector<PoseSolveResidual> poseSolveResiduals(const std::vector<cv::Point3f>& points,
	const std::vector<float>& relativeDepthStd, const Eigen::Vector3d& rayOrigin, const cv::Mat& rvec,
	const cv::Mat& tvec, const cv::Matx33d& K);

/** The covariance of an unweighted least-squares pose solve over
 * `residuals` with pixel noise sigmaPx on each, and each residual's
 * structure covariance on top: A^-1 (sum J^T W J) A^-1 with A = sum J^T J,
 * W = sigma^2 I + structure. Without structure it is sigma^2 A^-1. False
 * (and `covariance` untouched) when A is singular. */
bool poseCovariance(
	const std::vector<PoseSolveResidual>& residuals, double sigmaPx, Eigen::Matrix<double, 6, 6>& covariance);
}  // namespace vslam

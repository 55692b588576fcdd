#pragma once
/** \file WeightedPoseRefinement.h
 * A PnP pose refined with each point weighted by how well it is known.
 *
 * A landmark built from a short forward baseline knows the depth of the
 * points near its direction of motion to 10-30% and of those at the
 * image's edges to a few percent (StructureUncertainty.h). An unweighted
 * fit from the side lets the poorly known depths pull the pose; the
 * generalized least-squares fit weighs each inlier's reprojection error by
 * the inverse of its covariance, the pixel noise plus its point's depth
 * uncertainty carried into the image (sigma^2 I + J_X C_X J_X^T), and its
 * covariance is then (sum J^T W^-1 J)^-1, the structure included.
 */
#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <vector>

namespace vslam
{
/** Gauss-Newton on the whitened reprojection errors of `points` at
 * `pixels`, each weighted by sigmaPx^2 I plus the pixel covariance of its
 * depth std (`relativeDepthStd[k]` times its distance from `rayOrigin`,
 * along that ray; poseSolveResiduals()), from the pose X_cam = R(rvec) X +
 * tvec it is given. On success `rvec`, `tvec` hold the refined pose and
 * `covariance` its 6x6 covariance (rvec, tvec), scaled up by the fit's
 * reduced chi-square where that exceeds 1. False, with the pose untouched,
 * when the points do not determine a pose (fewer than 4, or singular). */
bool refinePoseWeightedByStructure(const std::vector<cv::Point3f>& points, const std::vector<cv::Point2f>& pixels,
	const std::vector<float>& relativeDepthStd, const Eigen::Vector3d& rayOrigin, const cv::Matx33d& K,
	double sigmaPx, cv::Mat& rvec, cv::Mat& tvec, Eigen::Matrix<double, 6, 6>& covariance);
}  // namespace vslam

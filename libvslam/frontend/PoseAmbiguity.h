#pragma once
/** \file PoseAmbiguity.h
 * A second camera pose that explains the same matches. A landmark's points
 * often lie on one surface (a wall, a picture); seen small or from afar,
 * a plane's pose is two-fold ambiguous: the solution with the plane's
 * normal mirrored about the line of sight reprojects almost as well
 * (Collins and Bartoli, IPPE, IJCV 2014). The two differ by tens of
 * degrees of viewing direction and up to metres of position, so a solve
 * that lands in the wrong one is not a noisy measurement but a wrong one,
 * and it lands there again frame after frame.
 *
 * competingPose() seeds Levenberg-Marquardt with both IPPE solutions for
 * the points projected onto their least-squares plane (IPPE takes only
 * coplanar points; the refinement uses the real ones) and returns the best local minimum of the
 * reprojection error that is not the given pose. Whether the matches
 * prefer the given pose clearly enough is the caller's test
 * (reprojectionCostGap()).
 */
#include <opencv2/core.hpp>

#include <optional>
#include <vector>

namespace vslam
{
/** A camera pose X_cam = R(rvec) X + tvec and its RMS reprojection error. */
struct CameraPoseFit
{
	cv::Vec3d rvec, tvec;
	double rmsPx = 0;
};

/** Differences below which two poses are one: rotation angle, and camera
 * centre distance as a share of the points' mean depth. */
struct SamePoseTolerance
{
	double rotationRad = 2.0 * CV_PI / 180;
	double centreShareOfDepth = 0.05;
};

/** The best pose for `object` -> `pixels` (undistorted, pinhole K; at least
 * 4 points) other than `pose`, each seed refined on all the points; empty
 * if every seed converges to `pose` or fails. */
std::optional<CameraPoseFit> competingPose(const std::vector<cv::Point3f>& object,
	const std::vector<cv::Point2f>& pixels, const cv::Matx33d& K, const CameraPoseFit& pose,
	const SamePoseTolerance& same = {});

/** How much more the competitor's squared reprojection errors sum to than
 * the pose's, over n points, in units of the pixel noise variance (taken
 * as the pose's RMS error, at least floorPx): a chi-square-like gap, small
 * or negative when the matches do not tell the two apart. */
double reprojectionCostGap(const CameraPoseFit& pose, const CameraPoseFit& competitor, size_t n, double floorPx = 0.5);
}  // namespace vslam

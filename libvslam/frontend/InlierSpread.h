#pragma once
/** \file InlierSpread.h
 * How widely a pose's inliers spread over the image, as viewing angles.
 * A pose solved from points that crowd into a thin strip of the image is
 * close to degenerate: rotation about the strip and translation across it
 * trade against each other. Worse, on a self-similar texture (grass, moss,
 * foliage) a handful of wrong matches inside such a strip can agree on a
 * coherent wrong pose with a small reprojection error and a small predicted
 * covariance, metres and tens of degrees from the truth.
 * The spread is the standard deviation of the inliers' normalized image
 * coordinates ((u - cx) / fx, (v - cy) / fy) along their minor principal
 * axis: an angle in radians (small-angle), independent of the image's
 * resolution and of how many points there are.
 */
#include <opencv2/core.hpp>

#include <vector>

namespace vslam
{
/** The std (rad) of the viewing directions of `pixels` (undistorted, pinhole
 * K) across the direction along which they vary least; 0 for fewer than
 * two points. */
double inlierMinorSpread(const std::vector<cv::Point2f>& pixels, const cv::Matx33d& K);
}  // namespace vslam

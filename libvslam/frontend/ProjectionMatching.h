#pragma once
/** \file ProjectionMatching.h
 * Matches a pose finds: each landmark point not yet matched is sought among
 * the image features near the pixel where the pose projects it (a guided
 * search, as ORB-SLAM's search by projection). The unguided ratio test
 * rejects a point whose descriptor has a near twin among the landmark's
 * points, and the one-to-one rule may give a point to a look-alike feature
 * elsewhere in the image; near the projected pixel such twins are rarely
 * left, so the geometry decides what the descriptors alone cannot.
 */
#include <opencv2/core.hpp>

#include <utility>
#include <vector>

namespace vslam
{
struct ProjectionMatchLimits
{
	double radiusPx = 0;  //!< features farther from the projected pixel are not considered
	/** The nearest feature in the window must be nearer than this times
	 * the second nearest, when the window holds two or more. */
	double ratio = 0.8;
	/** Largest accepted descriptor distance (e.g. the largest among the
	 * matches the pose was solved from). */
	double maxDistance = 0;
};

/** Matches (feature row, point row) from points to features: for each
 * point j with projectedValid[j] and not pointTaken[j], the features
 * within radiusPx of projected[j] that are not featureTaken; the nearest by
 * descriptor distance is j's match if it passes `limits`. A feature that
 * is the match of several points is kept for the nearest one only. Both
 * descriptor sets CV_32F with the same columns; the result is ordered by
 * point. */
std::vector<std::pair<int, int>> matchByProjection(const std::vector<cv::Point2f>& projected,
	const std::vector<bool>& projectedValid, const cv::Mat& pointDescriptors, const std::vector<bool>& pointTaken,
	const std::vector<cv::Point2f>& featurePixels, const cv::Mat& featureDescriptors,
	const std::vector<bool>& featureTaken, const ProjectionMatchLimits& limits);
}  // namespace vslam

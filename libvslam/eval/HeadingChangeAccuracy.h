#pragma once
/** \file HeadingChangeAccuracy.h
 * How right the front-end's heading changes between images are, against a
 * ground-truth path, next to what the wheel odometry said over the same
 * intervals: the error, how it compares with the std the estimate predicts
 * (its calibration), and how much
 * better than odometry it is.
 */
#include <libvslam/io/Trajectory.h>

#include <cstddef>
#include <vector>

namespace vslam
{
struct HeadingChangeRecord
{
	double t0 = 0, t1 = 0;  //!< the two images, UNIX s
	double dphi = 0;  //!< measured heading change, rad
	double stdDphi = 0;  //!< its predicted std, rad
	double odometryDphi = 0;  //!< the odometry's over the same interval, rad
	int inliers = 0, matches = 0;
	double rmsPx = 0;
};

/** One record with its truth. */
struct HeadingChangeError
{
	HeadingChangeRecord record;
	double trueDphi = 0;  //!< rad
};

struct HeadingChangeAccuracy
{
	size_t count = 0, withoutTruth = 0;
	double medianAbsErrorDeg = 0, rmsErrorDeg = 0;
	double medianPredictedStdDeg = 0;
	/** RMS of error / predicted std (1 where the prediction is right). */
	double rmsNormalizedError = 0;
	/** Median |error / predicted std| (0.674 for a right Gaussian prediction). */
	double medianAbsNormalizedError = 0;
	size_t beyond3Sigma = 0;  //!< beyond 3 predicted std
	/** The odometry's heading-change error over the same intervals. */
	double odometryMedianAbsErrorDeg = 0, odometryRmsErrorDeg = 0;
	/** Signed sum of the errors over all intervals (a bias shows), deg. */
	double sumErrorDeg = 0, odometrySumErrorDeg = 0;
	std::vector<HeadingChangeError> errors;  //!< those with truth, in input order
};

/** Each record against the truth's heading change from t0 to t1
 * (interpolated; records where the truth has no pose are counted apart). */
HeadingChangeAccuracy evaluateHeadingChanges(
	const std::vector<HeadingChangeRecord>& records, const Trajectory& truth);
}  // namespace vslam

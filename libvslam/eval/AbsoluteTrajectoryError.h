#pragma once
/** \file AbsoluteTrajectoryError.h
 * ATE as in Sturm et al. 2012 (TUM RGB-D benchmark), planar: every
 * estimated pose is associated with the ground truth interpolated at its
 * timestamp (or, for ground truth without timestamps, with the ground-truth
 * pose of the same rawlog step); the statistic is over the translational
 * (xy) errors, raw or after the least-squares SE(2) alignment of the
 * estimate onto the truth, or after the least-squares similarity (SE(2)
 * and a scale, Umeyama 1991; evo's --correct_scale), which says how much
 * of the error a map built too large or too small explains (wheel odometry
 * with a scale bias builds such a map, and nothing it measures can tell). */
#include <libvslam/eval/TrajectoryAssociation.h>
#include <libvslam/io/Trajectory.h>

#include <cstddef>

namespace vslam
{
struct AteStats
{
	size_t associated = 0;  //!< estimated poses with ground truth
	double rmse = 0, mean = 0, median = 0, max = 0;
	double headingRmse = 0;  //!< rad
	std::vector<double> errors;  //!< xy error per associated pose, in the estimate's order
	std::vector<double> headingErrors;  //!< signed, rad, per associated pose
	std::vector<double> times;  //!< the estimate's timestamp per associated pose
	/** The SE(2) transform applied to the estimate (identity unless
	 * aligned): estimate pose p is compared as compose(alignment, p). */
	se2::Pose alignment{0, 0, 0};
	/** The scale applied before it (1 unless aligned with a scale): the
	 * estimate's position x is compared as alignment applied to scale * x;
	 * headings are not scaled. */
	double alignmentScale = 1;
};

struct TAteOptions
{
	/** Longest ground-truth gap to interpolate across (s). */
	double maxGap = 0.5;
	/** Align the estimate onto the truth with the best SE(2) first. */
	bool align = false;
	/** With align: the best similarity instead (a scale as well). */
	bool alignScale = false;
};

AteStats computeAte(
	const Trajectory& estimate, const Trajectory& groundTruth,
	const TAteOptions& options = {});
}  // namespace vslam

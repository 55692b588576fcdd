#pragma once
/** \file TrajectoryAssociation.h
 * Pairs every estimated pose with its ground truth (Sturm et al. 2012):
 * the ground truth interpolated at the estimate's timestamp, or, for ground
 * truth without timestamps (MRPT per-step pose lists), the ground-truth pose
 * of the same rawlog step. Poses without ground truth are left out. Shared
 * by the absolute and the relative error. */
#include <libvslam/io/Trajectory.h>

#include <vector>

namespace vslam
{
struct AssociatedPose
{
	double t = 0;  //!< the estimate's timestamp (NaN if it has none)
	se2::Pose estimate, truth;
};

/** True if the ground truth has no timestamps (associate by step). */
bool hasOnlySteps(const Trajectory& groundTruth);

/** The associated pairs in the estimate's order; maxGap: the longest
 * ground-truth gap (s) interpolated across. */
std::vector<AssociatedPose> associate(
	const Trajectory& estimate, const Trajectory& groundTruth, double maxGap);
}  // namespace vslam

#pragma once
/** \file GroundTruthCheck.h
 * Whether a ground truth belongs to a run: an INI's ground_truth_file is
 * applied to whatever rawlog the command line gives, and another run's
 * truth must not pass silently as error figures. */
#include <libvslam/io/Trajectory.h>

namespace vslam
{
/** Share of the steps of `path` at whose time the truth has a pose. */
double groundTruthCover(const Trajectory& path, const Trajectory& truth);

/** Over one-second windows in which the odometry or the truth moved, the
 * share in which the two disagree far beyond any odometry error: the motion
 * in the robot's frame differing by more than half the larger plus 0.1 m,
 * or the turn by more than half the larger plus 10 deg. NaN with fewer than
 * 5 such windows. A run's own truth disagrees in a few windows (a kidnap, a
 * slip); another run's (another path, or this one mirrored) in most. */
double odometryDisagreement(const Trajectory& odometry, const Trajectory& truth);
}  // namespace vslam

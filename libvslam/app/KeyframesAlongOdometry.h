#pragma once
/** \file KeyframesAlongOdometry.h
 * The pose graph's solution at every step of the run, not only at its
 * keyframes: between two keyframes the odometry carries each of them to
 * the step, and the two are blended by time, so the path passes through
 * every keyframe and its mismatch with the odometry is spread over the
 * interval. Before the first keyframe and after the last, the one keyframe
 * there is carried alone. A path at every step is what the online estimate
 * and the dead reckoning are scored on, so the three compare like for like.
 */
#include <libvslam/io/Trajectory.h>

namespace vslam
{
/** keyframes and odometry sorted by time; the result has odometry's times
 * (empty without keyframes). Keyframes whose times do not strictly
 * increase are returned as they are. */
Trajectory keyframesAlongOdometry(const Trajectory& keyframes, const Trajectory& odometry);
}  // namespace vslam

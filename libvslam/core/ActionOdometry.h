#pragma once
/** \file ActionOdometry.h
 * The odometry increment of an action collection. MRPT's
 * getBestMovementEstimation() silently skips a movement whose increment is
 * NaN (its covariance is then NaN too), which would turn bad odometry into
 * "no motion"; this takes the first CActionRobotMovement2D as it is. */
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/poses/CPose2D.h>

#include <optional>

namespace vslam
{
inline std::optional<mrpt::poses::CPose2D> odometryIncrement(
	const mrpt::obs::CActionCollection& actions)
{
	const auto mv = actions.getActionByClass<mrpt::obs::CActionRobotMovement2D>();
	if (!mv || !mv->poseChange) return std::nullopt;
	return mv->poseChange->getMeanVal();
}

/** The time of the first CActionRobotMovement2D's reading, if it has one. */
inline std::optional<mrpt::Clock::time_point> odometryTime(const mrpt::obs::CActionCollection& actions)
{
	const auto mv = actions.getActionByClass<mrpt::obs::CActionRobotMovement2D>();
	if (!mv || mv->timestamp == INVALID_TIMESTAMP) return std::nullopt;
	return mv->timestamp;
}
}  // namespace vslam

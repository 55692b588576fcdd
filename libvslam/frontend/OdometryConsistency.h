#pragma once
/** \file OdometryConsistency.h
 * A recognition checked against the same landmark's previous one, carried
 * to now by the odometry. On self-similar textures (grass, moss) a handful
 * of wrong matches can agree on a coherent pose metres and tens of degrees
 * off, with a small reprojection error and a small predicted covariance;
 * nothing in the one image tells it from a right one. Such
 * recognitions alternate with right ones of the same landmark within a
 * second, and the odometry over that second rules the jump out. The
 * front-end has no map, only the odometry; over a few seconds its drift is
 * centimetres, so the tolerance can be tight.
 */
#include <mrpt/math/TPose2D.h>
#include <mrpt/poses/CPose2D.h>

#include <optional>

namespace vslam
{
/** A reported recognition of a landmark: when, the robot's odometry pose
 * then, and the landmark frame measured in the robot frame. Plain poses:
 * every landmark keeps one (56 bytes; with CPose2D's 96 each, 200). */
struct ReportedRecognition
{
	double time = 0;  //!< s
	mrpt::math::TPose2D odometryPose;
	mrpt::math::TPose2D landmarkInRobot;
};

struct TOdometryConsistencyOptions
{
	double horizon = 0;  //!< s: an earlier recognition older than this is not used (0: no check)
	double position = 0.3;  //!< m: position tolerance ...
	double relative = 0.1;  //!< ... plus this share of the measured distance
	double heading = 10 * M_PI / 180;  //!< rad
};

/** Where the odometry puts the landmark frame in the robot frame at
 * `odometryNow`, from the earlier recognition. */
mrpt::poses::CPose2D predictFromEarlier(
	const ReportedRecognition& earlier, const mrpt::poses::CPose2D& odometryNow);

/** Whether `landmarkInRobot`, measured at `time` and `odometryNow`, agrees
 * with the earlier recognition carried by the odometry: within `position`
 * + `relative` x its distance, and `heading`. With no earlier recognition,
 * one older than the horizon or later than `time`, or the check off: true. */
bool agreesWithOdometry(const std::optional<ReportedRecognition>& earlier, double time,
	const mrpt::poses::CPose2D& odometryNow, const mrpt::poses::CPose2D& landmarkInRobot,
	const TOdometryConsistencyOptions& tolerance);
}  // namespace vslam

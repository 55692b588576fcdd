#pragma once
/** \file LandmarkScaleOracle.h
 * What a landmark's scale error costs: its measurements with the scale
 * taken out, for `vslam-frontend --oracle-kind scale`.
 *
 * A landmark built k times too large (its lengths over the true ones)
 * measures the camera's position in the landmark frame k times too far from
 * the frame's origin; the heading is not scaled, and the camera's mount on
 * the robot is in metres. Over a landmark's measurements with truth, the
 * least-squares k of the measured camera positions c_m against the true
 * ones c_t is
 *
 *     k = sum <c_m, c_t> / sum |c_t|^2
 *
 * and dividing each measured camera position by k leaves the measurement's
 * other errors (its own noise, a turned landmark) in place.
 */
#include <libvslam/models/SE2.h>

#include <utility>
#include <vector>

namespace vslam
{
/** The camera's position in the landmark frame from a measurement z (the
 * landmark frame in the robot frame) and the camera's mount on the robot
 * (its planar part). */
se2::Pose cameraInLandmark(const se2::Pose& z, const se2::Pose& mount);

/** z with the camera's position in the landmark frame divided by k. */
se2::Pose withoutScale(const se2::Pose& z, const se2::Pose& mount, double k);

/** The least-squares scale of measured against true measurements (pairs
 * measured, true) of one landmark; 1 when the true camera positions are
 * all at the origin (nothing measures it). */
double fitLandmarkScale(const std::vector<std::pair<se2::Pose, se2::Pose>>& measuredAndTrue, const se2::Pose& mount);
}  // namespace vslam

#pragma once
/** \file OdometryDelay.h
 * How long after its odometry rows a robot actually moves, estimated from
 * its own range-bearing sightings, with no ground truth. Odometry that logs
 * the commanded twist (MRCLAM's) leads the motion by the drive's response
 * time; integrated as logged, every turn starts too early, and the heading
 * is off by omega x delay whenever the turn rate changes.
 *
 * A landmark seen twice within a short interval changes its bearing by what
 * the robot did in between: db = -dtheta + ds sin(b) / r (the turn, and the
 * parallax of the distance travelled). For a trial delay tau, dtheta and ds
 * are integrated from the odometry rows over the interval moved back by tau;
 * the delay is the one whose predicted bearing changes fit the measured
 * ones best (a truncated least squares over a grid of delays, so that a
 * misdetection counts as much as a poor fit and no more). The pairs in
 * turns that start or stop carry the information; the others fit any delay
 * alike.
 */
#include <optional>
#include <vector>

namespace vslam
{
struct TOdometryDelayOptions
{
	double minDelay = -0.5, maxDelay = 1.0, step = 0.01;  //!< the grid, s
	double maxPairInterval = 0.5;  //!< s between the two sightings of a pair
	double minRange = 0.5;  //!< m: nearer sightings have too much parallax
	double truncation = 0.05;  //!< rad of bearing-change residual
	size_t minPairs = 30;  //!< fewer: no estimate
};

/** One landmark sighting. */
struct BearingSighting
{
	double t = 0;  //!< s
	int landmark = 0;
	double range = 0;  //!< m
	double bearing = 0;  //!< rad
};

/** odometryRows: (t, v, omega) sorted by t, each held until the next;
 * sightings in any order. nullopt when too few pairs of sightings fall
 * inside the odometry's span. */
std::optional<double> estimateOdometryDelay(const std::vector<std::vector<double>>& odometryRows,
	std::vector<BearingSighting> sightings, const TOdometryDelayOptions& o = {});
}  // namespace vslam

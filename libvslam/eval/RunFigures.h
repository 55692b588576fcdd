#pragma once
/** \file RunFigures.h
 * The paper's figures for any run, as PNG files in one folder:
 *  - paths.png: estimate (aligned if asked), odometry, ground truth and the
 *    map's landmarks over the floor plan (its Fig. 2);
 *  - error_over_time.png: position error of the estimate and of odometry
 *    alone over time (its Fig. 4);
 *  - measurements_per_landmark.png (its Fig. 5);
 *  - particle_spread.png and dual_ratio.png: the particle cloud's spread and
 *    the share of dual (measurement-driven) particles over time.
 * True kidnaps (jumps of the ground truth) and the kidnaps the filter
 * declared are marked on the time plots. The last three need a vslam
 * output folder (final_map.txt, log_filter_steps.txt). */
#include <libvslam/io/Trajectory.h>
#include <libvslam/world/FloorPlan.h>

#include <string>
#include <vector>

namespace vslam
{
struct RunFigureSources
{
	const Trajectory* estimate = nullptr;
	const Trajectory* truth = nullptr;
	const Trajectory* odometry = nullptr;  //!< optional
	const world::FloorPlan* plan = nullptr;  //!< optional
	/** A vslam output folder, or "" (then only the first two figures). */
	std::string runDir;
	/** Applied to the estimate (and the map) before drawing and the error:
	 * identity, or computeAte's alignment. */
	se2::Pose alignment{0, 0, 0};
	double maxGap = 0.5;  //!< ground-truth interpolation, as for the ATE
};

/** Writes the figures into \a folder (created if missing); returns the
 * files written. Throws InputError on unreadable inputs or outputs. */
std::vector<std::string> writeRunFigures(const RunFigureSources& sources, const std::string& folder);

/** Fig. 2 alone: the estimate (moved by the alignment; labelled "estimate
 * (aligned)" unless that is the identity), the ground truth with its jumps
 * as thin lines, the odometry if given and \a landmarks, over the floor plan
 * if given. Throws InputError if the file cannot be written. */
void writePathsFigure(
	const RunFigureSources& sources, const std::vector<se2::Pose>& landmarks, const std::string& pngFile);

/** Where a ground truth jumps (a kidnap): the indices i whose step from
 * i - 1 is over 0.5 m and over 20 times the median step. */
std::vector<size_t> truthJumps(const Trajectory& truth);
}  // namespace vslam

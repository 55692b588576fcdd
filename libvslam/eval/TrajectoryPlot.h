#pragma once
/** \file TrajectoryPlot.h
 * Paths drawn over a floor plan as a PNG (the paper's Fig. 2 style):
 * walls and furniture grey, each path in its colour with a legend, jumps
 * (kidnaps) as thin lines, landmarks as arrows, a 1 m scale. Without a floor plan the view
 * fits the paths. */
#include <libvslam/io/Trajectory.h>
#include <libvslam/world/FloorPlan.h>

#include <string>
#include <vector>

namespace vslam
{
struct PlotSeries
{
	const Trajectory* path = nullptr;
	std::array<uint8_t, 3> rgb{0, 0, 0};
	std::string label;
	/** Indices i at which the path jumps (from i - 1): drawn thin. */
	std::vector<size_t> jumps;
};

/** \a landmarks (optional): the map's landmark frames, drawn as small
 * arrows along their heading (in the frame the paths are drawn in). */
void writeTrajectoryPlot(const world::FloorPlan* plan, const std::vector<PlotSeries>& series, const std::string& pngFile,
	const std::vector<se2::Pose>& landmarks = {});
}  // namespace vslam

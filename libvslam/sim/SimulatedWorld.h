#pragma once
/** \file SimulatedWorld.h
 * The world a rendered simulation runs in: the world file, or the home the
 * generator makes from world_seed (whose start becomes the robot's, unless
 * the path is a waypoint loop).
 */
#include <libvslam/sim/CVisualSimulator.h>
#include <libvslam/world/FloorPlan.h>

#include <string>

namespace vslam
{
struct SimulatedWorld
{
	world::FloorPlan plan;
	/** The generated home as a world file (empty for a world file). */
	std::string generatedText;
};

/** Loads or generates the world; for a generated home, sets the options'
 * start_pose to its start. InputError naming the file and line. */
SimulatedWorld loadSimulatedWorld(CVisualSimulator::TOptions& options);
}  // namespace vslam

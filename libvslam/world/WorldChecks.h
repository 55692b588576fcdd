#pragma once
/** \file WorldChecks.h
 * Geometry a world must not have, whoever made it (a world file or the
 * home generator): two openings overlapping on a wall, furniture or a box
 * through a wall, a picture above the ceiling. Each is an InputError
 * naming the world file and the item's line.
 */
#include <libvslam/world/FloorPlan.h>

namespace vslam::world
{
void checkWorldGeometry(const FloorPlan& plan);

/** The wall (index) the footprint goes through by more than 2 cm, or -1. */
int wallThrough(const FloorPlan& plan, const std::vector<Eigen::Vector2d>& footprint);
}  // namespace vslam::world

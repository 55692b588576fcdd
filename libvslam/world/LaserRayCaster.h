#pragma once
/** \file LaserRayCaster.h
 * A planar laser scanner in the floor plan: exact ray casting against the
 * obstacle outlines and round moving obstacles (people).
 */
#include <libvslam/world/FloorPlan.h>

#include <vector>

namespace vslam::world
{
struct Circle
{
	Eigen::Vector2d centre;
	double radius = 0.2;
};

/** Distance along the ray from `origin` in unit direction `dir` to the
 * first obstacle, or +infinity if none is hit. */
double castRay(
	const std::vector<Segment>& segments, const std::vector<Circle>& circles, const Eigen::Vector2d& origin,
	const Eigen::Vector2d& dir);
}  // namespace vslam::world

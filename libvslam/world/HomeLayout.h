#pragma once
/** \file HomeLayout.h
 * A generated home's shell: a rectangular footprint cut into rooms 2.5-8 m
 * across, either along a hallway 1.1-1.5 m wide (rooms on both sides) or
 * around an open living and kitchen area; walls between them (outer
 * 0.2 m, inner 0.1 m, each face painted for its room), a doorway with an
 * open leaf from every room to the hallway or living area, and windows in
 * the outer walls.
 */
#include <libvslam/world/FloorPlan.h>
#include <libvslam/world/HomeStyle.h>
#include <libvslam/world/SeededRandom.h>

#include <vector>

namespace vslam::world
{
struct HomeRoom
{
	RoomKind kind;
	Eigen::Vector2d lo, hi;  //!< the rectangle between wall centre lines
	/** The room's inner floor (walls' faces), per side south, east,
	 * north, west: is that side an outer wall. */
	std::array<bool, 4> outer{false, false, false, false};
	int paint = -1;  //!< its walls' material
	int featureWall = -1;  //!< the side wallpapered instead, or -1
	Eigen::Vector2d innerLo() const;
	Eigen::Vector2d innerHi() const;
};

struct HomeLayout
{
	std::vector<HomeRoom> rooms;
	size_t hub = 0;  //!< the hallway or the living area every room opens to
};

/** Rooms, walls, doorways and windows into `plan`. */
HomeLayout buildHomeLayout(FloorPlan& plan, const HomeStyle& style, SeededRandom& rng);

/** Half the thickness of outer and inner walls. */
constexpr double kOuterHalf = 0.1, kInnerHalf = 0.05;
}  // namespace vslam::world

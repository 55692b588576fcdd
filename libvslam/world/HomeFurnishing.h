#pragma once
/** \file HomeFurnishing.h
 * Furnishes a generated home's rooms as people do: furniture with its
 * back to the walls (a sofa facing a TV across a coffee table, a bed with
 * bedside tables, a run of kitchen units under wall cabinets), a table
 * with chairs where there is room, a radiator under every window, lamps on
 * the ceilings, and a few pictures on the walls (one of them hung twice).
 * Doorways and the start keep clear; an item that would cut a room off
 * from the rest is left out.
 */
#include <libvslam/world/HomeLayout.h>

namespace vslam::world
{
/** Adds furniture and pictures to the plan; `start` stays free. */
void furnishHome(FloorPlan& plan, const HomeLayout& layout, const HomeStyle& style, const Eigen::Vector2d& start,
	SeededRandom& rng);
}  // namespace vslam::world

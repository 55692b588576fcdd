#pragma once
/** \file HomeGenerator.h
 * Plausible homes from a seed, so that any number of unseen homes exist:
 * rooms 2.5-8 m across along a hallway or around an open living area,
 * doorways between them, windows in the outer walls, furniture along the
 * walls, a few pictures, painted walls, parquet, tiles and carpet
 * (HomeLayout.h, HomeFurnishing.h, HomeStyle.h). Every room can be
 * reached from the start; the same seed gives the same home.
 */
#include <libvslam/models/SE2.h>
#include <libvslam/world/FloorPlan.h>

#include <cstdint>
#include <string>

namespace vslam::world
{
struct GeneratedHome
{
	FloorPlan plan;
	std::string worldText;  //!< the plan as a world file (FloorPlanFile.h)
	se2::Pose start;  //!< a free pose in the hallway or living area
	/** Each room's floor between its walls' faces. */
	struct Room
	{
		std::string kind;
		Eigen::Vector2d lo, hi;
	};
	std::vector<Room> rooms;
};

/** The home of `seed`; textureDir: where the packages' files are (the
 * plan's textures and models are resolved there). */
GeneratedHome generateHome(uint32_t seed, const std::string& textureDir);
}  // namespace vslam::world

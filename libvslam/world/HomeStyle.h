#pragma once
/** \file HomeStyle.h
 * What a generated home is made of and decorated with, all from Debian
 * packages (doc/textures.md): paints (Sweet Home 3D's plaster photograph,
 * tinted, its contrast lowered), floors (parquet, tiles, carpet), the
 * views seen through the windows, and the posters, paintings and photos
 * hung on a minority of the walls. A style picks one set per home.
 */
#include <libvslam/world/FloorPlan.h>
#include <libvslam/world/SeededRandom.h>

#include <string>
#include <vector>

namespace vslam::world
{
enum class RoomKind
{
	Living,
	LivingKitchen,
	Kitchen,
	Bedroom,
	Study,
	Hall
};

struct HomeStyle
{
	std::vector<int> paints;  //!< wall materials, by room (index into plan.materials)
	int ceiling = -1, skirting = -1, door = -1;
	int woodFloor = -1, tiles = -1, carpet = -1, hallFloor = -1;
	int wallTiles = -1;  //!< behind the kitchen counter
	int wallpaper = -1;  //!< on a feature wall of some living rooms and bedrooms
	std::vector<TextureRef> views;  //!< seen through the windows
	std::vector<TextureRef> pictures;  //!< posters, paintings, photos
	const FurnitureItem* radiator = nullptr;  //!< the same model under every window
	double skirtingHeight = 0.08;

	/** The floor of a room of this kind. */
	TextureRef floorFor(RoomKind kind) const;
};

/** Adds the home's materials to the plan and picks its style; `rooms`
 * paints are drawn per room. textureDir: where the packages' files are. */
HomeStyle makeHomeStyle(FloorPlan& plan, size_t rooms, SeededRandom& rng);

/** A material reference. */
TextureRef materialRef(int index);
}  // namespace vslam::world

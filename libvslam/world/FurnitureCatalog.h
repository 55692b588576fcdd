#pragma once
/** \file FurnitureCatalog.h
 * The furniture, fittings and people of the rendered homes: 3-D models
 * from Debian's sweethome3d-furniture package (photographic textures of
 * wood, fabric, books, metal), with the sizes and mounting heights its
 * Sweet Home 3D catalogues give them. World files name them
 * ("furniture X Y FACING NAME", FloorPlanFile.h); the home generator picks
 * them by role. Licences: doc/textures.md.
 */
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace vslam::world
{
enum class FurnitureRole
{
	Sofa,
	Armchair,
	CoffeeTable,
	TvStand,
	Tv,
	Bookcase,
	Fireplace,
	Piano,
	Plant,
	FloorLamp,
	CeilingLamp,
	DiningTable,
	Chair,
	Bed,
	BedsideTable,
	Wardrobe,
	Dresser,
	Desk,
	DeskChair,
	KitchenLower,
	KitchenSink,
	KitchenStove,
	KitchenTall,
	KitchenUpper,
	Appliance,
	Radiator,
	ClosedDoor,
	Person,
	Decor,  //!< stands on furniture: vases, lamps, radios, frames
	KitchenDecor,  //!< stands on kitchen counters
	Switch,  //!< on the wall beside a doorway
	WallDecor,  //!< hangs on a wall: a clock
	Clutter  //!< stands on the floor: boxes, baskets, a guitar
};

struct FurnitureItem
{
	std::string name;
	FurnitureRole role;
	/** The OBJ model, relative to the texture folder (an archive member:
	 * AssetArchive.h). */
	std::string model;
	double width, depth, height;  //!< m: along its front, front to back, up
	double elevation;  //!< m above the floor (wall cabinets, lamps)
	/** Sweet Home 3D's model rotation (row-major 3x3, applied to the model
	 * before it is fitted to its size), or empty. */
	std::vector<double> modelRotation;

	/** Is in the robot's way: reaches below 0.5 m (a wall cabinet or a
	 * ceiling lamp does not). */
	bool isObstacle() const { return elevation < 0.5; }
};

/** Every item, in a fixed order. */
const std::vector<FurnitureItem>& furnitureCatalog();

/** The item called `name`, or nullptr. */
const FurnitureItem* findFurniture(const std::string& name);

/** The items of one role, in catalogue order. */
std::vector<const FurnitureItem*> furnitureOfRole(FurnitureRole role);

/** Where the package keeps the catalogue's archives, under the texture folder. */
constexpr const char* kFurnitureArchiveDir = "sweethome3d/furniture/";
}  // namespace vslam::world

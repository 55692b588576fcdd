#pragma once
/** \file FloorPlan.h
 * An indoor world for the rendered simulator: walls with their doorways
 * and windows, floors, furniture (3-D models or textured boxes), pictures
 * and door leaves, each surface a photograph or a material tiled at its
 * real size, and the 2-D obstacle outline that the laser, the robot's
 * path planning and the preview use. Parsed from a world file
 * (FloorPlanFile.h) or made by the home generator (HomeGenerator.h).
 */
#include <libvslam/world/FurnitureCatalog.h>

#include <Eigen/Core>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace vslam::world
{
/** A photograph tiled at its real size (plaster, paint, parquet, tiles):
 * one copy covers tileWidth x tileHeight metres. The tint (a paint's
 * colour, 0-1 per RGB channel) multiplies it after its contrast around the
 * mean has been scaled by `contrast` (0: flat paint, 1: as photographed). */
struct Material
{
	std::string name;
	std::string file;  //!< an asset path (AssetArchive.h), checked when parsed
	double tileWidth = 1, tileHeight = 1;  //!< m
	std::array<double, 3> tint{1, 1, 1};  //!< R, G, B
	double contrast = 1;
	int line = 0;
};

/** What a surface shows: a part of a photograph, stretched to the surface
 * once without distortion ("nature/Wood.jpg@0,0,0.5,1" is its left half; a
 * trailing "~" mirrors it left-right, which SIFT sees as new content), or
 * a material repeated over it. */
struct TextureRef
{
	std::string file;  //!< the photograph (empty when a material is used)
	double u0 = 0, v0 = 0, u1 = 1, v1 = 1;
	bool mirrored = false;
	int material = -1;  //!< index into FloorPlan::materials, or -1
};

/** A 2-D segment of an obstacle's outline, with where it was defined. */
struct Segment
{
	Eigen::Vector2d a, b;
	int line = 0;  //!< world-file line of the item it belongs to
};

/** A vertical wall from a to b, floor to ceiling. The front face is on the
 * left when walking from a to b (walls listed counter-clockwise face into
 * the room); the back face is textured only if `back` is set. */
struct Wall
{
	Eigen::Vector2d a, b;
	double thickness = 0.1;
	TextureRef front;
	bool hasBack = false;
	TextureRef back;
	int line = 0;
};

/** A hole through a wall: a doorway (from the floor; the robot passes) or
 * a window (a view outside, behind the wall's back face). Along the wall
 * from s0 to s1 metres, from z0 to z1. */
struct Opening
{
	enum class Kind { Doorway, Window } kind = Kind::Doorway;
	size_t wall = 0;  //!< index into FloorPlan::walls
	double s0 = 0, s1 = 1, z0 = 0, z1 = 2.05;
	/** Window: the photograph seen through it. Doorway: the open door
	 * leaf's texture, if it has a leaf (standing at right angles to the
	 * wall, hinged at one end of the doorway, on one side of the wall). */
	TextureRef texture;
	bool hasLeaf = false;
	bool hingeAtS0 = true;  //!< the leaf's hinge is at s0 (else at s1)
	bool leafToFront = true;  //!< the leaf stands on the wall's front side
	int line = 0;
};

/** Furniture: a box standing on the floor, every side and its top
 * textured (a cupboard, a shelf, a table block, a sofa). */
struct Box
{
	Eigen::Vector2d centre;
	double yaw = 0;  //!< rad
	double sizeX = 1, sizeY = 1, height = 1;
	TextureRef texture;
	int line = 0;
};

/** A catalogue model (FurnitureCatalog.h) with the centre of its
 * footprint at `centre`, its front facing `facing`, its base at
 * `elevation` above the floor. */
struct Furniture
{
	const FurnitureItem* item = nullptr;
	Eigen::Vector2d centre{0, 0};
	double facing = 0;  //!< rad
	double elevation = 0;  //!< m
	int line = 0;
};

/** A picture hanging on the front face of a wall-like line a -> b, from
 * height z0 to z1, a few mm in front of it, in a frame; or, unframed, a
 * panel covering the wall there (tiles behind a kitchen counter). Not an
 * obstacle. */
struct Picture
{
	Eigen::Vector2d a, b;
	double z0 = 1, z1 = 1.5;
	TextureRef texture;
	int line = 0;
	bool framed = true;
};

/** A door leaf (open, standing in the room): a thin panel from a to b,
 * 2 m high, textured on both faces. An obstacle. */
struct Door
{
	Eigen::Vector2d a, b;
	double height = 2.0;
	TextureRef texture;
	int line = 0;
};

/** A floor covering over the axis-aligned rectangle lo..hi (a room's
 * parquet, a kitchen's tiles), above the base floor. */
struct FloorArea
{
	Eigen::Vector2d lo, hi;
	TextureRef texture;
	int line = 0;
};

struct FloorPlan
{
	std::string sourceFile;
	std::string textureDir;  //!< the folder texture and model paths were resolved in
	double ceilingHeight = 2.5;  //!< m
	bool hasFloorTexture = false;
	TextureRef floor;
	bool hasCeilingTexture = false;
	TextureRef ceiling;
	/** Skirting boards along every wall face, this high (0: none). */
	double skirtingHeight = 0;
	TextureRef skirting;
	std::vector<Material> materials;
	std::vector<Wall> walls;
	std::vector<Opening> openings;
	std::vector<FloorArea> floorAreas;
	std::vector<Box> boxes;
	std::vector<Furniture> furniture;
	std::vector<Picture> pictures;
	std::vector<Door> doors;

	/** Every obstacle outline: both faces of each wall (but its doorways),
	 * box and furniture footprints, door leaves. What the laser sees and
	 * the robot must not cross. */
	std::vector<Segment> obstacleSegments() const;
	/** The solid parts as convex polygons (walls between their doorways,
	 * boxes, furniture): a point inside one is in an obstacle even if far
	 * from its outline. */
	std::vector<std::vector<Eigen::Vector2d>> solidPolygons() const;
	/** Bounding box of all obstacles (min, max). */
	std::pair<Eigen::Vector2d, Eigen::Vector2d> bounds() const;
	/** The parts of wall i between its doorways, as [s0, s1] along it. */
	std::vector<std::pair<double, double>> wallPieces(size_t i) const;
	/** The openings of wall i, ordered along it. */
	std::vector<const Opening*> openingsOf(size_t i) const;
	/** Share of the walls' textured face area covered by (framed)
	 * pictures: a world's decorated share. */
	double decoratedWallShare() const;
};

/** The four corners of a box's footprint, counter-clockwise. */
std::vector<Eigen::Vector2d> footprint(const Box& b);
/** The four corners of a furniture item's footprint, counter-clockwise. */
std::vector<Eigen::Vector2d> footprint(const Furniture& f);
/** The hinge side and the free end of a doorway's open leaf. */
std::pair<Eigen::Vector2d, Eigen::Vector2d> doorLeaf(const FloorPlan& plan, const Opening& doorway);
/** The outline of wall w from s0 to s1 metres along it, counter-clockwise. */
std::vector<Eigen::Vector2d> wallOutline(const Wall& w, double s0, double s1);
/** Point s metres along wall w's centre line. */
Eigen::Vector2d alongWall(const Wall& w, double s);
/** p inside (or on) a counter-clockwise convex polygon. */
bool insideConvex(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p);
/** Two convex polygons overlap by more than `margin` (separating axes). */
bool convexOverlap(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b, double margin);
}  // namespace vslam::world

#pragma once
/** \file FloorPlan.h
 * An indoor world for the rendered simulator: walls, furniture boxes,
 * pictures on walls and door leaves, each textured with a photograph, and
 * the 2-D obstacle outline that the laser, the robot's path planning and
 * the preview use. Parsed from a world file (FloorPlanFile.h).
 */
#include <Eigen/Core>

#include <string>
#include <vector>

namespace vslam::world
{
/** A photograph (file) and the part of it used, as fractions of its width
 * and height: "nature/Wood.jpg@0,0,0.5,1" is its left half; a trailing
 * "~" mirrors it left-right (SIFT descriptors of a mirrored image do not
 * match the original's, so a mirrored part counts as new content). */
struct TextureRef
{
	std::string file;  //!< absolute path, checked to exist when parsed
	double u0 = 0, v0 = 0, u1 = 1, v1 = 1;
	bool mirrored = false;
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

/** A picture hanging on the front face of a wall-like line a -> b, from
 * height z0 to z1, a few mm in front of it. Not an obstacle. */
struct Picture
{
	Eigen::Vector2d a, b;
	double z0 = 1, z1 = 1.5;
	TextureRef texture;
	int line = 0;
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

struct FloorPlan
{
	std::string sourceFile;
	double ceilingHeight = 2.5;  //!< m
	bool hasFloorTexture = false;
	TextureRef floor;
	std::vector<Wall> walls;
	std::vector<Box> boxes;
	std::vector<Picture> pictures;
	std::vector<Door> doors;

	/** Every obstacle outline: both faces of each wall, box footprints,
	 * door leaves. What the laser sees and the robot must not cross. */
	std::vector<Segment> obstacleSegments() const;
	/** The solid parts as convex polygons (walls, boxes): a point inside
	 * one is in an obstacle even if far from its outline. */
	std::vector<std::vector<Eigen::Vector2d>> solidPolygons() const;
	/** Bounding box of all obstacles (min, max). */
	std::pair<Eigen::Vector2d, Eigen::Vector2d> bounds() const;
};

/** The four corners of a box's footprint, counter-clockwise. */
std::vector<Eigen::Vector2d> footprint(const Box& b);
/** p inside (or on) a counter-clockwise convex polygon. */
bool insideConvex(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p);
}  // namespace vslam::world

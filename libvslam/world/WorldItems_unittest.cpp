/** The world file's home items (materials, floor areas, doorways,
 * windows, furniture, skirting) and the checks every world must pass:
 * doorways open the wall to the robot, furniture blocks it, an unknown
 * texture, furniture through a wall, a doorway or window off any wall and
 * overlapping openings are errors naming the file and line; a plan written
 * out reads back the same. */
#include <gtest/gtest.h>
#include <libvslam/core/InputError.h>
#include <libvslam/world/FloorPlanFile.h>
#include <libvslam/world/FreeSpace.h>
#include <libvslam/world/LaserRayCaster.h>

#include <filesystem>
#include <fstream>

using namespace vslam::world;

namespace
{
std::string textureDir()
{
	const auto dir = std::filesystem::temp_directory_path() / "vslam_world_items_textures";
	std::filesystem::create_directories(dir);
	std::ofstream(dir / "paint.jpg") << "x";
	std::ofstream(dir / "view.jpg") << "x";
	return dir.string();
}

// Two rooms, 4 x 3 m each, side by side; a doorway between them at
// y 1.0-1.9, a window in the south wall of the west room.
const char* kHome =
	"ceiling_height 2.5\n"
	"material plaster paint.jpg 0.5 0.5 tint=240,236,228 contrast=0.3\n"
	"floor plaster\n"
	"floor paint.jpg 4 0 8 3\n"
	"skirting 0.08 plaster\n"
	"wall 0 0 8 0 0.2 plaster\n"  // line 6
	"wall 8 0 8 3 0.2 plaster\n"
	"wall 8 3 0 3 0.2 plaster\n"
	"wall 0 3 0 0 0.2 plaster\n"
	"wall 4 0 4 3 0.1 plaster plaster\n"  // line 10
	"doorway 4 1.0 4 1.9 2.05 paint.jpg front\n"
	"window 1 0 2.2 0 0.9 2.1 view.jpg\n"
	"furniture 2 2.5 -90 sofa_beige\n"
	"furniture 6 0.3 90 kitchen_upper\n";

std::string errorOf(const std::string& text)
{
	try
	{
		parseFloorPlan(text, "home.world", textureDir());
	}
	catch (const vslam::InputError& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(WorldItems, ParsesMaterialsOpeningsAndFurniture)
{
	const FloorPlan p = parseFloorPlan(kHome, "home.world", textureDir());
	ASSERT_EQ(p.materials.size(), 1u);
	EXPECT_NEAR(p.materials[0].tint[0], 240 / 255.0, 1e-12);
	EXPECT_DOUBLE_EQ(p.materials[0].contrast, 0.3);
	EXPECT_EQ(p.walls[0].front.material, 0);
	ASSERT_EQ(p.floorAreas.size(), 1u);
	ASSERT_EQ(p.openings.size(), 2u);
	const Opening& door = p.openings[0];
	EXPECT_EQ(door.wall, 4u);
	EXPECT_NEAR(door.s0, 1.0, 1e-9);
	EXPECT_NEAR(door.s1, 1.9, 1e-9);
	EXPECT_TRUE(door.hasLeaf && door.hingeAtS0 && door.leafToFront);
	EXPECT_EQ(p.openings[1].kind, Opening::Kind::Window);
	ASSERT_EQ(p.furniture.size(), 2u);
	EXPECT_EQ(p.furniture[0].item->name, "sofa_beige");
	EXPECT_NEAR(p.furniture[1].elevation, 1.45, 1e-9);  // the catalogue's wall-cabinet height
	EXPECT_FALSE(p.furniture[1].item->isObstacle());
	EXPECT_NEAR(p.decoratedWallShare(), 0, 1e-12);
}

TEST(WorldItems, DoorwaysLetTheRobotThroughAndFurnitureBlocksIt)
{
	const FloorPlan p = parseFloorPlan(kHome, "home.world", textureDir());
	EXPECT_EQ(p.wallPieces(4).size(), 2u);
	const FreeSpace fs(p, 0.2, {1, 1.5});
	EXPECT_TRUE(fs.isFree({6, 1.5}));  // the east room, through the doorway
	EXPECT_TRUE(fs.segmentIsFree({3, 1.45}, {5, 1.45}));
	EXPECT_FALSE(fs.isFree({2, 2.5}));  // the sofa
	EXPECT_TRUE(fs.isFree({6, 0.5}));  // under the wall cabinet
	// The laser passes through the doorway to the east wall, not through the window.
	const auto segs = p.obstacleSegments();
	EXPECT_NEAR(castRay(segs, {}, {3, 1.45}, {1, 0}), 8 - 0.1 - 3, 1e-9);
	EXPECT_NEAR(castRay(segs, {}, {1.6, 1}, {0, -1}), 1 - 0.1, 1e-9);
	// The open leaf stands in the west room's side, from the hinge at y = 1.0.
	const auto [hinge, end] = doorLeaf(p, p.openings[0]);
	EXPECT_LT(hinge[0], 4);
	EXPECT_NEAR(end[0], hinge[0] - 0.87, 1e-9);
}

TEST(WorldItems, BadHomesAreErrorsNamingTheFileAndLine)
{
	const std::string h = kHome;
	EXPECT_NE(errorOf("wall 0 0 1 0 0.1 brick\n").find("home.world' line 1: unknown texture 'brick'"), std::string::npos);
	EXPECT_NE(errorOf(h + "furniture 7.9 1.5 180 bookcase_books\n").find("line 15: furniture 'bookcase_books' goes through the wall on line 7"),
		std::string::npos);
	EXPECT_NE(errorOf(h + "furniture 1 1 0 no_such_sofa\n").find("line 15: unknown furniture 'no_such_sofa'"), std::string::npos);
	EXPECT_NE(errorOf(h + "doorway 2 1 2 1.9 2.05\n").find("line 15: 'doorway'"), std::string::npos);
	EXPECT_NE(errorOf(h + "doorway 2 1 2 1.9 2.05\n").find("is not on a wall"), std::string::npos);
	EXPECT_NE(errorOf(h + "window 9 0 9.5 0 1 2 view.jpg\n").find("is not on a wall"), std::string::npos);
	EXPECT_NE(errorOf(h + "window 1.5 0 3 0 1 2 view.jpg\n").find("line 15: this opening overlaps the one on line 12"),
		std::string::npos);
	EXPECT_NE(errorOf(h + "box 0.05 1.5 0 0.5 0.5 1 paint.jpg\n").find("line 15: the box goes through the wall on line 9"),
		std::string::npos);
	EXPECT_NE(errorOf("material m paint.jpg 0.5 0.5 tint=300,0,0\nwall 0 0 1 0 0.1 m\n").find("line 1: bad material option"),
		std::string::npos);
	EXPECT_NE(errorOf("material a.b paint.jpg 1 1\n").find("may not contain"), std::string::npos);
	EXPECT_NE(errorOf(h + "furniture 2 1.5 0 wardrobe_sliding 0.5\n").find("reaches above the ceiling"), std::string::npos);
	EXPECT_NE(errorOf(h + "doorway 4 2 4 2.8 2.05 paint.jpg sideways\n").find("'front' or 'back'"), std::string::npos);
}

TEST(WorldItems, AWrittenPlanReadsBackTheSame)
{
	const std::string dir = textureDir();
	const FloorPlan p = parseFloorPlan(kHome, "home.world", dir);
	const std::string text = floorPlanText(p, dir);
	const FloorPlan q = parseFloorPlan(text, "again.world", dir);
	EXPECT_EQ(floorPlanText(q, dir), text);
	ASSERT_EQ(q.openings.size(), p.openings.size());
	EXPECT_NEAR(q.openings[0].s0, p.openings[0].s0, 1e-4);
	EXPECT_EQ(q.openings[0].leafToFront, p.openings[0].leafToFront);
	EXPECT_EQ(q.obstacleSegments().size(), p.obstacleSegments().size());
}

TEST(WorldItems, ConvexOverlapSeparatesTouchingShapes)
{
	const std::vector<Eigen::Vector2d> a{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
	const std::vector<Eigen::Vector2d> touching{{1, 0}, {2, 0}, {2, 1}, {1, 1}};
	const std::vector<Eigen::Vector2d> into{{0.9, 0.2}, {2, 0.2}, {2, 0.8}, {0.9, 0.8}};
	EXPECT_FALSE(convexOverlap(a, touching, 0.02));
	EXPECT_TRUE(convexOverlap(a, into, 0.02));
	EXPECT_FALSE(convexOverlap(a, into, 0.2));  // within the margin
}

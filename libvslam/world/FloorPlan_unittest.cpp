/** World file parsing, free space and the laser ray caster against a
 * floor plan with known geometry. */
#include <gtest/gtest.h>
#include <libvslam/core/InputError.h>
#include <libvslam/world/FloorPlanFile.h>
#include <libvslam/world/FreeSpace.h>
#include <libvslam/world/LaserRayCaster.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace vslam::world;

namespace
{
/** A texture folder with one small image file (the parser only checks
 * that texture files exist). */
std::string textureDir()
{
	const auto dir = std::filesystem::temp_directory_path() / "vslam_world_test_textures";
	std::filesystem::create_directories(dir);
	std::ofstream(dir / "photo.jpg") << "x";
	return dir.string();
}

const char* kRoom =
	"# 4 x 3 m room, walls counter-clockwise, a box in it\n"
	"ceiling_height 2.4\n"
	"floor photo.jpg\n"
	"wall 0 0 4 0 0.1 photo.jpg\n"
	"wall 4 0 4 3 0.1 photo.jpg@0,0,0.5,1\n"
	"wall 4 3 0 3 0.1 photo.jpg\n"
	"wall 0 3 0 0 0.1 photo.jpg photo.jpg@0.5,0,1,1~\n"
	"box 3 2 0 1 0.5 0.8 photo.jpg\n"
	"picture 1 2.95 2 2.95 1.2 1.8 photo.jpg\n";

std::string errorOf(const std::string& text)
{
	try
	{
		parseFloorPlan(text, "w.world", textureDir());
	}
	catch (const vslam::InputError& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(FloorPlanFile, ParsesEveryItem)
{
	const FloorPlan p = parseFloorPlan(kRoom, "room.world", textureDir());
	EXPECT_DOUBLE_EQ(p.ceilingHeight, 2.4);
	ASSERT_EQ(p.walls.size(), 4u);
	EXPECT_EQ(p.walls[1].line, 5);
	EXPECT_DOUBLE_EQ(p.walls[1].front.u1, 0.5);
	EXPECT_TRUE(p.walls[3].hasBack);
	EXPECT_FALSE(p.walls[3].front.mirrored);
	EXPECT_TRUE(p.walls[3].back.mirrored);
	EXPECT_DOUBLE_EQ(p.walls[3].back.u0, 0.5);
	ASSERT_EQ(p.boxes.size(), 1u);
	EXPECT_DOUBLE_EQ(p.boxes[0].height, 0.8);
	EXPECT_EQ(p.pictures.size(), 1u);
	EXPECT_TRUE(p.hasFloorTexture);
	EXPECT_EQ(p.obstacleSegments().size(), 4u * 4 + 4);
}

TEST(FloorPlanFile, BadFilesNameTheFileLineAndProblem)
{
	EXPECT_NE(errorOf("wall 0 0 1 0 0.1 nosuch.jpg\n").find("line 1: unknown texture 'nosuch.jpg'"), std::string::npos);
	EXPECT_NE(errorOf("# nothing\n").find("'w.world': empty world"), std::string::npos);
	EXPECT_NE(errorOf("wal 0 0 1 0 0.1 photo.jpg\n").find("line 1: unknown item 'wal'"), std::string::npos);
	EXPECT_NE(errorOf("wall 0 0 1 0 photo.jpg\n").find("takes X1 Y1 X2 Y2"), std::string::npos);
	EXPECT_NE(errorOf("wall 0 0 1 nan 0.1 photo.jpg\n").find("bad y 'nan'"), std::string::npos);
	EXPECT_NE(errorOf("wall 0 0 0 0 0.1 photo.jpg\n").find("zero length"), std::string::npos);
	EXPECT_NE(errorOf("wall 0 0 1 0 -1 photo.jpg\n").find("thickness must be positive"), std::string::npos);
	EXPECT_NE(errorOf("wall 0 0 1 0 0.1 photo.jpg@0,0,2,1\n").find("bad texture part"), std::string::npos);
	EXPECT_NE(errorOf(std::string(kRoom) + "picture 0 0 1 0 2 3 photo.jpg\n").find("above the ceiling"),
		std::string::npos);
	EXPECT_THROW(loadFloorPlan("/nonexistent/x.world", textureDir()), vslam::InputError);
}

TEST(FreeSpace, ReachableRegionIsTheRoomMinusTheRobotRadius)
{
	const FloorPlan p = parseFloorPlan(kRoom, "room.world", textureDir());
	const FreeSpace fs(p, 0.2, {1, 1});
	EXPECT_TRUE(fs.isFree({1, 1}));
	EXPECT_FALSE(fs.isFree({0.2, 1}));  // 0.15 m from the wall's face
	EXPECT_FALSE(fs.isFree({3, 2}));  // inside the box
	EXPECT_FALSE(fs.isFree({5, 1}));  // outside
	// Free area: (4 - 0.1 - 0.4) x (3 - 0.1 - 0.4) minus the inflated box.
	const double room = 3.5 * 2.5, box = 1.4 * 0.9 - (4 - M_PI) * 0.04;
	EXPECT_NEAR(fs.freeArea(), room - box, 0.25);
	EXPECT_TRUE(fs.segmentIsFree({0.5, 0.5}, {3.4, 0.5}));
	EXPECT_FALSE(fs.segmentIsFree({1.5, 2}, {3.4, 2}));  // through the box
	EXPECT_EQ(fs.blockingSegment({1.5, 2}, {3.4, 2})->line, 8);
	for (double u : {0.0, 0.3, 0.999}) EXPECT_TRUE(fs.isFree(fs.freeCell(u)));
}

TEST(FreeSpace, OpenWorldsAndBlockedStartsAreErrors)
{
	const std::string open = "wall 0 0 4 0 0.1 photo.jpg\nwall 4 0 4 3 0.1 photo.jpg\n";
	const FloorPlan p = parseFloorPlan(open, "open.world", textureDir());
	EXPECT_THROW(FreeSpace(p, 0.2, {2, 1}), vslam::InputError);
	const FloorPlan room = parseFloorPlan(kRoom, "room.world", textureDir());
	EXPECT_THROW(FreeSpace(room, 0.2, {3, 2}), vslam::InputError);
}

TEST(LaserRayCaster, RangesAgreeWithTheFloorPlan)
{
	const FloorPlan p = parseFloorPlan(kRoom, "room.world", textureDir());
	const auto segs = p.obstacleSegments();
	const Eigen::Vector2d o(1, 1);
	EXPECT_NEAR(castRay(segs, {}, o, {1, 0}), 4 - 0.05 - 1, 1e-9);  // east wall face
	EXPECT_NEAR(castRay(segs, {}, o, {-1, 0}), 1 - 0.05, 1e-9);
	EXPECT_NEAR(castRay(segs, {}, o, {0, 1}), 3 - 0.05 - 1, 1e-9);
	const Eigen::Vector2d diag = Eigen::Vector2d(1, 1).normalized();
	EXPECT_NEAR(castRay(segs, {}, o, diag), 1.95 * std::sqrt(2.0), 1e-9);  // passes above the box
	EXPECT_NEAR(castRay(segs, {}, {1, 2}, {1, 0}), 1.5, 1e-9);  // the box's west side
	EXPECT_NEAR(castRay(segs, {{{2, 1}, 0.25}}, o, {1, 0}), 0.75, 1e-9);  // a person
}

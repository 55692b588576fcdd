/** Generated homes against what the generator promises: the same seed
 * gives the same home, rooms are 2.5-8 m across, every room and doorway can
 * be reached from the start, the systematic tour and planned paths keep
 * clear of every obstacle, windows are only in outer walls, and pictures
 * cover a minority of the walls. Skipped without the texture packages. */
#include <gtest/gtest.h>
#include <libvslam/world/AssetArchive.h>
#include <libvslam/world/FreeSpace.h>
#include <libvslam/world/HomeGenerator.h>
#include <libvslam/world/PathPlanner.h>

#include <filesystem>

using namespace vslam::world;

namespace
{
const std::string kTextures = "/usr/share";

bool packagesInstalled()
{
	return std::filesystem::is_directory(kTextures + "/sweethome3d/furniture") &&
		std::filesystem::is_regular_file(kTextures + "/sweethome3d/sweethome3d.jar");
}

#define SKIP_WITHOUT_PACKAGES() \
	if (!packagesInstalled()) GTEST_SKIP() << "sweethome3d and sweethome3d-furniture are not installed (scripts/setup.sh installs them)"
}  // namespace

TEST(HomeGenerator, TheSameSeedGivesTheSameHome)
{
	SKIP_WITHOUT_PACKAGES();
	const GeneratedHome a = generateHome(7, kTextures), b = generateHome(7, kTextures), c = generateHome(8, kTextures);
	EXPECT_EQ(a.worldText, b.worldText);
	EXPECT_NE(a.worldText, c.worldText);
	EXPECT_EQ(a.start.x, b.start.x);
}

TEST(HomeGenerator, EveryRoomIsReachableAndItsPathsAreCollisionFree)
{
	SKIP_WITHOUT_PACKAGES();
	for (uint32_t seed = 1; seed <= 12; seed++)
	{
		SCOPED_TRACE("home " + std::to_string(seed));
		const GeneratedHome h = generateHome(seed, kTextures);
		ASSERT_GE(h.rooms.size(), 3u);
		const FreeSpace free(h.plan, 0.2, {h.start.x, h.start.y});
		// Rooms 2.5-8 m across (between wall centre lines), each with free floor the robot reaches.
		for (const auto& r : h.rooms)
		{
			const Eigen::Vector2d size = r.hi - r.lo;
			if (r.kind != "hallway") { EXPECT_GE(size.minCoeff(), 2.5 - 0.2 - 1e-9) << r.kind; }
			EXPECT_LE(size.maxCoeff(), 14.0) << r.kind;
			int reachable = 0;
			for (double x = r.lo[0]; x < r.hi[0]; x += 0.1)
				for (double y = r.lo[1]; y < r.hi[1]; y += 0.1) reachable += free.isFree({x, y});
			EXPECT_GT(reachable * 0.01, 0.5) << r.kind << " at (" << r.lo.transpose() << ")";
		}
		for (const Opening& o : h.plan.openings)
		{
			const Wall& w = h.plan.walls[o.wall];
			const Eigen::Vector2d mid = alongWall(w, 0.5 * (o.s0 + o.s1));
			if (o.kind == Opening::Kind::Doorway)
				EXPECT_TRUE(free.isFree(mid)) << "doorway on line " << o.line;
			else
				EXPECT_DOUBLE_EQ(w.thickness, 0.2) << "a window in an inner wall, line " << o.line;
		}
		// The systematic tour's legs and planned paths through the home.
		const auto tour = homeTour(free, {h.start.x, h.start.y});
		ASSERT_GT(tour.size(), h.rooms.size());
		for (size_t i = 0; i < tour.size(); i++) EXPECT_TRUE(free.segmentIsFree(tour[i], tour[(i + 1) % tour.size()]));
		const PathPlanner planner(free);
		for (double u : {0.1, 0.5, 0.9})
		{
			const Eigen::Vector2d goal = free.freeCell(u);
			Eigen::Vector2d at(h.start.x, h.start.y);
			const auto legs = planner.plan(at, goal);
			ASSERT_FALSE(legs.empty());
			for (const auto& corner : legs)
			{
				EXPECT_TRUE(free.segmentIsFree(at, corner)) << at.transpose() << " -> " << corner.transpose();
				at = corner;
			}
			EXPECT_LT((at - goal).norm(), 1e-9);
		}
		EXPECT_GT(h.plan.decoratedWallShare(), 0.02);
		EXPECT_LT(h.plan.decoratedWallShare(), 0.2);
	}
}

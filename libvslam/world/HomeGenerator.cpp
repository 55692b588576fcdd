#include <libvslam/world/FloorPlanFile.h>
#include <libvslam/world/HomeFurnishing.h>
#include <libvslam/world/HomeGenerator.h>
#include <libvslam/world/HomeLayout.h>

#include <cstdio>

namespace vslam::world
{
namespace
{
const char* kindName(RoomKind k)
{
	switch (k)
	{
		case RoomKind::Living: return "living room";
		case RoomKind::LivingKitchen: return "living room and kitchen";
		case RoomKind::Kitchen: return "kitchen";
		case RoomKind::Bedroom: return "bedroom";
		case RoomKind::Study: return "study";
		default: return "hallway";
	}
}

std::string header(uint32_t seed, const HomeLayout& layout, const FloorPlan& plan)
{
	std::string h = "# Home " + std::to_string(seed) + " of vslam's home generator (vslam_simul.world_seed = " +
		std::to_string(seed) + "), rooms:\n";
	for (const HomeRoom& r : layout.rooms)
	{
		char line[160];
		std::snprintf(line, sizeof line, "#   %s, %.1f x %.1f m at (%.1f, %.1f)\n", kindName(r.kind), r.hi[0] - r.lo[0],
			r.hi[1] - r.lo[1], r.lo[0], r.lo[1]);
		h += line;
	}
	char share[120];
	std::snprintf(share, sizeof share, "# Pictures cover %.1f%% of the wall area; items: FloorPlanFile.h.\n",
		100 * plan.decoratedWallShare());
	return h + share;
}
}  // namespace

GeneratedHome generateHome(uint32_t seed, const std::string& textureDir)
{
	SeededRandom rng(0x9E3779B97F4A7C15ull ^ seed);
	FloorPlan plan;
	plan.textureDir = textureDir;
	plan.ceilingHeight = rng.uniform(2.45, 2.75);
	const HomeStyle style = makeHomeStyle(plan, 12, rng);  // a paint for each room (at most 9)
	const HomeLayout layout = buildHomeLayout(plan, style, rng);
	plan.floor = materialRef(style.woodFloor), plan.hasFloorTexture = true;
	for (const HomeRoom& r : layout.rooms) plan.floorAreas.push_back({r.lo, r.hi, style.floorFor(r.kind), 0});
	plan.ceiling = materialRef(style.ceiling), plan.hasCeilingTexture = true;
	plan.skirtingHeight = style.skirtingHeight, plan.skirting = materialRef(style.skirting);
	const HomeRoom& hub = layout.rooms[layout.hub];
	const Eigen::Vector2d start = 0.5 * (hub.innerLo() + hub.innerHi());
	furnishHome(plan, layout, style, start, rng);

	GeneratedHome home;
	const std::string name = "home_" + std::to_string(seed) + ".world";
	home.worldText = header(seed, layout, plan) + floorPlanText(plan, textureDir);
	// Read back as any world file is: its checks, and lines to name in errors.
	home.plan = parseFloorPlan(home.worldText, name, textureDir);
	const Eigen::Vector2d span = hub.innerHi() - hub.innerLo();
	home.start = {start[0], start[1], span[0] >= span[1] ? (rng.chance(0.5) ? 0.0 : M_PI) : (rng.chance(0.5) ? M_PI / 2 : -M_PI / 2)};
	for (const HomeRoom& r : layout.rooms) home.rooms.push_back({kindName(r.kind), r.innerLo(), r.innerHi()});
	return home;
}
}  // namespace vslam::world

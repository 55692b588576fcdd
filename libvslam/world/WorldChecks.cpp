#include <libvslam/core/InputError.h>
#include <libvslam/world/WorldChecks.h>

namespace vslam::world
{
namespace
{
[[noreturn]] void fail(const FloorPlan& plan, int line, const std::string& what)
{
	throw InputError("world file '" + plan.sourceFile + "' line " + std::to_string(line) + ": " + what);
}

void checkOpenings(const FloorPlan& plan)
{
	for (size_t i = 0; i < plan.walls.size(); i++)
	{
		const auto openings = plan.openingsOf(i);
		for (size_t k = 1; k < openings.size(); k++)
			if (openings[k]->s0 < openings[k - 1]->s1 - 1e-6)
				fail(plan, openings[k]->line,
					"this opening overlaps the one on line " + std::to_string(openings[k - 1]->line) +
						" in the wall on line " + std::to_string(plan.walls[i].line));
	}
}
}  // namespace

int wallThrough(const FloorPlan& plan, const std::vector<Eigen::Vector2d>& footprint)
{
	for (size_t i = 0; i < plan.walls.size(); i++)
		for (const auto& [s0, s1] : plan.wallPieces(i))
			if (convexOverlap(wallOutline(plan.walls[i], s0, s1), footprint, 0.02)) return static_cast<int>(i);
	return -1;
}

void checkWorldGeometry(const FloorPlan& plan)
{
	checkOpenings(plan);
	for (const Box& b : plan.boxes)
		if (const int w = wallThrough(plan, footprint(b)); w >= 0)
			fail(plan, b.line, "the box goes through the wall on line " + std::to_string(plan.walls[w].line));
	for (const Furniture& f : plan.furniture)
		if (const int w = wallThrough(plan, footprint(f)); w >= 0)
			fail(plan, f.line,
				"furniture '" + f.item->name + "' goes through the wall on line " + std::to_string(plan.walls[w].line));
	for (const Picture& q : plan.pictures)
		if (q.z1 > plan.ceilingHeight) fail(plan, q.line, "picture reaches above the ceiling");
}
}  // namespace vslam::world

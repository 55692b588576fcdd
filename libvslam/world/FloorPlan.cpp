#include <libvslam/world/FloorPlan.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vslam::world
{
namespace
{
Eigen::Vector2d unit(const Wall& w) { return (w.b - w.a).normalized(); }
Eigen::Vector2d frontNormal(const Wall& w)
{
	const Eigen::Vector2d d = unit(w);
	return {-d[1], d[0]};
}

std::vector<Eigen::Vector2d> rectangle(const Eigen::Vector2d& centre, double yaw, double sizeX, double sizeY)
{
	const Eigen::Vector2d ax(std::cos(yaw), std::sin(yaw)), ay(-ax[1], ax[0]);
	const double hx = sizeX / 2, hy = sizeY / 2;
	return {centre - hx * ax - hy * ay, centre + hx * ax - hy * ay, centre + hx * ax + hy * ay,
			centre - hx * ax + hy * ay};
}

void addOutline(const std::vector<Eigen::Vector2d>& poly, int line, std::vector<Segment>& out)
{
	for (size_t i = 0; i < poly.size(); i++) out.push_back({poly[i], poly[(i + 1) % poly.size()], line});
}
}  // namespace

Eigen::Vector2d alongWall(const Wall& w, double s) { return w.a + s * unit(w); }

std::vector<Eigen::Vector2d> wallOutline(const Wall& w, double s0, double s1)
{
	const Eigen::Vector2d off = 0.5 * w.thickness * frontNormal(w);
	const Eigen::Vector2d a = alongWall(w, s0), b = alongWall(w, s1);
	return {a - off, b - off, b + off, a + off};
}

std::vector<Eigen::Vector2d> footprint(const Box& b) { return rectangle(b.centre, b.yaw, b.sizeX, b.sizeY); }

std::vector<Eigen::Vector2d> footprint(const Furniture& f)
{
	// Its width runs across the facing direction, its depth along it.
	return rectangle(f.centre, f.facing + M_PI / 2, f.item->width, f.item->depth);
}

std::pair<Eigen::Vector2d, Eigen::Vector2d> doorLeaf(const FloorPlan& plan, const Opening& d)
{
	const Wall& w = plan.walls.at(d.wall);
	const Eigen::Vector2d side = (d.leafToFront ? 1.0 : -1.0) * frontNormal(w);
	const Eigen::Vector2d hinge = alongWall(w, d.hingeAtS0 ? d.s0 : d.s1) + (0.5 * w.thickness + 0.03) * side;
	return {hinge, hinge + (d.s1 - d.s0 - 0.03) * side};
}

std::vector<const Opening*> FloorPlan::openingsOf(size_t i) const
{
	std::vector<const Opening*> out;
	for (const Opening& o : openings)
		if (o.wall == i) out.push_back(&o);
	std::sort(out.begin(), out.end(), [](const Opening* x, const Opening* y) { return x->s0 < y->s0; });
	return out;
}

std::vector<std::pair<double, double>> FloorPlan::wallPieces(size_t i) const
{
	const double len = (walls.at(i).b - walls.at(i).a).norm();
	std::vector<std::pair<double, double>> out;
	double from = 0;
	for (const Opening* o : openingsOf(i))
	{
		if (o->kind != Opening::Kind::Doorway) continue;
		if (o->s0 > from) out.emplace_back(from, o->s0);
		from = std::max(from, o->s1);
	}
	if (from < len) out.emplace_back(from, len);
	return out;
}

std::vector<Segment> FloorPlan::obstacleSegments() const
{
	std::vector<Segment> out;
	for (size_t i = 0; i < walls.size(); i++)
		for (const auto& [s0, s1] : wallPieces(i)) addOutline(wallOutline(walls[i], s0, s1), walls[i].line, out);
	for (const Box& b : boxes) addOutline(footprint(b), b.line, out);
	for (const Furniture& f : furniture)
		if (f.item->isObstacle()) addOutline(footprint(f), f.line, out);
	for (const Door& d : doors) out.push_back({d.a, d.b, d.line});
	for (const Opening& o : openings)
		if (o.kind == Opening::Kind::Doorway && o.hasLeaf)
		{
			const auto [hinge, end] = doorLeaf(*this, o);
			out.push_back({hinge, end, o.line});
		}
	return out;
}

std::vector<std::vector<Eigen::Vector2d>> FloorPlan::solidPolygons() const
{
	std::vector<std::vector<Eigen::Vector2d>> out;
	for (size_t i = 0; i < walls.size(); i++)
		for (const auto& [s0, s1] : wallPieces(i)) out.push_back(wallOutline(walls[i], s0, s1));
	for (const Box& b : boxes) out.push_back(footprint(b));
	for (const Furniture& f : furniture)
		if (f.item->isObstacle()) out.push_back(footprint(f));
	return out;
}

double FloorPlan::decoratedWallShare() const
{
	double wallArea = 0, decorated = 0;
	for (const Wall& w : walls) wallArea += (w.hasBack ? 2 : 1) * (w.b - w.a).norm() * ceilingHeight;
	for (const Picture& p : pictures)
		if (p.framed) decorated += (p.b - p.a).norm() * (p.z1 - p.z0);
	return wallArea > 0 ? decorated / wallArea : 0;
}

bool insideConvex(const std::vector<Eigen::Vector2d>& poly, const Eigen::Vector2d& p)
{
	for (size_t i = 0; i < poly.size(); i++)
	{
		const Eigen::Vector2d e = poly[(i + 1) % poly.size()] - poly[i], q = p - poly[i];
		if (e[0] * q[1] - e[1] * q[0] < 0) return false;
	}
	return !poly.empty();
}

bool convexOverlap(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b, double margin)
{
	// Separated along some edge normal of either polygon, by more than
	// -margin (a shared boundary within the margin is no overlap).
	for (const auto* poly : {&a, &b})
		for (size_t i = 0; i < poly->size(); i++)
		{
			const Eigen::Vector2d e = (*poly)[(i + 1) % poly->size()] - (*poly)[i];
			const Eigen::Vector2d n = Eigen::Vector2d(-e[1], e[0]).normalized();
			double aMin = 1e300, aMax = -1e300, bMin = 1e300, bMax = -1e300;
			for (const auto& p : a) aMin = std::min(aMin, n.dot(p)), aMax = std::max(aMax, n.dot(p));
			for (const auto& p : b) bMin = std::min(bMin, n.dot(p)), bMax = std::max(bMax, n.dot(p));
			if (aMax < bMin + margin || bMax < aMin + margin) return false;
		}
	return true;
}

std::pair<Eigen::Vector2d, Eigen::Vector2d> FloorPlan::bounds() const
{
	constexpr double inf = std::numeric_limits<double>::infinity();
	Eigen::Vector2d lo(inf, inf), hi(-inf, -inf);
	for (const Segment& s : obstacleSegments())
	{
		lo = lo.cwiseMin(s.a).cwiseMin(s.b);
		hi = hi.cwiseMax(s.a).cwiseMax(s.b);
	}
	return {lo, hi};
}
}  // namespace vslam::world

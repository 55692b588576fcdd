#include <libvslam/world/FloorPlan.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vslam::world
{
std::vector<Eigen::Vector2d> footprint(const Box& b)
{
	const Eigen::Vector2d ax(std::cos(b.yaw), std::sin(b.yaw)), ay(-ax[1], ax[0]);
	const double hx = b.sizeX / 2, hy = b.sizeY / 2;
	return {b.centre - hx * ax - hy * ay, b.centre + hx * ax - hy * ay,
			b.centre + hx * ax + hy * ay, b.centre - hx * ax + hy * ay};
}

std::vector<Segment> FloorPlan::obstacleSegments() const
{
	std::vector<Segment> out;
	for (const Wall& w : walls)
	{
		const Eigen::Vector2d d = (w.b - w.a).normalized();
		const Eigen::Vector2d n(-d[1], d[0]);  // towards the front face
		const Eigen::Vector2d off = 0.5 * w.thickness * n;
		out.push_back({w.a + off, w.b + off, w.line});
		out.push_back({w.a - off, w.b - off, w.line});
		out.push_back({w.a + off, w.a - off, w.line});
		out.push_back({w.b + off, w.b - off, w.line});
	}
	for (const Box& b : boxes)
	{
		const auto c = footprint(b);
		for (size_t i = 0; i < c.size(); i++) out.push_back({c[i], c[(i + 1) % c.size()], b.line});
	}
	for (const Door& d : doors) out.push_back({d.a, d.b, d.line});
	return out;
}

std::vector<std::vector<Eigen::Vector2d>> FloorPlan::solidPolygons() const
{
	std::vector<std::vector<Eigen::Vector2d>> out;
	for (const Wall& w : walls)
	{
		const Eigen::Vector2d d = (w.b - w.a).normalized(), n(-d[1], d[0]);
		const Eigen::Vector2d off = 0.5 * w.thickness * n;
		out.push_back({w.a - off, w.b - off, w.b + off, w.a + off});
	}
	for (const Box& b : boxes) out.push_back(footprint(b));
	return out;
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

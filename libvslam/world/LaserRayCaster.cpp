#include <libvslam/world/LaserRayCaster.h>

#include <cmath>
#include <limits>

namespace vslam::world
{
double castRay(
	const std::vector<Segment>& segments, const std::vector<Circle>& circles, const Eigen::Vector2d& origin,
	const Eigen::Vector2d& dir)
{
	double best = std::numeric_limits<double>::infinity();
	for (const Segment& s : segments)
	{
		// origin + t dir = s.a + u (s.b - s.a)
		const Eigen::Vector2d e = s.b - s.a, w = s.a - origin;
		const double den = dir[0] * (-e[1]) - dir[1] * (-e[0]);
		if (std::abs(den) < 1e-12) continue;
		const double t = (w[0] * (-e[1]) - w[1] * (-e[0])) / den;
		const double u = (dir[0] * w[1] - dir[1] * w[0]) / den;
		if (t > 0 && u >= 0 && u <= 1 && t < best) best = t;
	}
	for (const Circle& c : circles)
	{
		const Eigen::Vector2d m = origin - c.centre;
		const double b = m.dot(dir), q = m.squaredNorm() - c.radius * c.radius;
		const double disc = b * b - q;
		if (disc < 0) continue;
		const double t = -b - std::sqrt(disc);
		if (t > 0 && t < best) best = t;
	}
	return best;
}
}  // namespace vslam::world

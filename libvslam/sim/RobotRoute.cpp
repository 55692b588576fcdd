#include <libvslam/core/InputError.h>
#include <libvslam/sim/RobotRoute.h>

#include <cmath>
#include <cstdio>

namespace vslam
{
namespace
{
using Path = CVisualSimulator::TOptions::PathType;

std::string describe(const Eigen::Vector2d& p)
{
	char buf[64];
	std::snprintf(buf, sizeof(buf), "(%.2f, %.2f)", p[0], p[1]);
	return buf;
}
}  // namespace

RobotRoute::RobotRoute(const CVisualSimulator::TOptions& o, const world::FreeSpace& freeSpace, mrpt::random::CRandomGenerator& rng)
	: m_o(o), m_free(freeSpace), m_rng(rng), m_planner(freeSpace)
{
	m_start = {o.start_pose[0], o.start_pose[1], o.start_pose[2] * M_PI / 180};
	if (o.path_type == Path::Waypoints)
		for (size_t i = 0; i + 1 < o.waypoints.size(); i += 2) m_loop.emplace_back(o.waypoints[i], o.waypoints[i + 1]);
	else if (o.path_type == Path::Tour)
	{
		m_loop = world::homeTour(freeSpace, {m_start.x, m_start.y});
		if (m_loop.size() < 3) throw InputError("[vslam_simul] path_type=tour: the home has no room to tour from " + describe({m_start.x, m_start.y}));
		if ((m_loop.back() - m_loop.front()).norm() < 1e-6) m_loop.pop_back();
	}
	if (o.path_type == Path::Waypoints)
		m_start = {m_loop[0][0], m_loop[0][1], std::atan2(m_loop[1][1] - m_loop[0][1], m_loop[1][0] - m_loop[0][0])};
}

Eigen::Vector2d RobotRoute::firstGoal()
{
	if (looped()) return m_loop[m_next % m_loop.size()];
	return nextGoal(m_start);
}

Eigen::Vector2d RobotRoute::nextGoal(const se2::Pose& p)
{
	if (looped())
	{
		m_next++;
		if (m_next % m_loop.size() == 1) m_laps++;  // back at the loop's first point
		return m_loop[m_next % m_loop.size()];
	}
	return m_o.path_type == Path::Roam ? roamGoal(p) : goalInSight(p);
}

Eigen::Vector2d RobotRoute::goalInSight(const se2::Pose& from)
{
	const Eigen::Vector2d p(from.x, from.y);
	for (int attempt = 0; attempt < 2000; attempt++)
	{
		const Eigen::Vector2d g = m_free.freeCell(m_rng.drawUniform(0, 1));
		if ((g - p).norm() > 0.5 && m_free.segmentIsFree(p, g)) return g;
	}
	throw InputError("no collision-free goal in sight of " + describe(p) + ": the free space is too cramped");
}

Eigen::Vector2d RobotRoute::roamGoal(const se2::Pose& from)
{
	const Eigen::Vector2d p(from.x, from.y);
	for (int attempt = 0; m_legs.empty() && attempt < 200; attempt++)
	{
		const Eigen::Vector2d g = m_free.freeCell(m_rng.drawUniform(0, 1));
		if ((g - p).norm() < 1.5) continue;
		const auto legs = m_planner.plan(p, g);
		m_legs.assign(legs.begin(), legs.end());
	}
	if (m_legs.empty()) return goalInSight(from);
	const Eigen::Vector2d g = m_legs.front();
	m_legs.pop_front();
	return g;
}

void RobotRoute::record(const se2::Pose& p) { m_visits.push_back({p, m_next}); }

se2::Pose RobotRoute::kidnap(const se2::Pose& from, Eigen::Vector2d& goal)
{
	// A pose the robot had, far enough from here; if it has been nowhere
	// far enough yet, anywhere.
	std::vector<const Visit*> far;
	if (m_o.kidnap_target == CVisualSimulator::TOptions::KidnapTarget::Visited)
		for (const Visit& v : m_visits)
			if (std::hypot(v.pose.x - from.x, v.pose.y - from.y) >= m_o.kidnap_min_distance) far.push_back(&v);
	se2::Pose to = from;
	if (!far.empty())
	{
		const Visit& v = *far[static_cast<size_t>(m_rng.drawUniform32bit() % far.size())];
		to = v.pose;
		if (looped()) m_next = v.next;
	}
	else
		for (int attempt = 0; attempt < 1000; attempt++)
		{
			if (looped())
			{
				m_next = static_cast<size_t>(m_rng.drawUniform32bit() % m_loop.size());
				const Eigen::Vector2d at = m_loop[m_next], next = m_loop[(m_next + 1) % m_loop.size()];
				to = {at[0], at[1], std::atan2(next[1] - at[1], next[0] - at[0])};
				m_next++;
			}
			else
			{
				const Eigen::Vector2d at = m_free.freeCell(m_rng.drawUniform(0, 1));
				to = {at[0], at[1], m_rng.drawUniform(-M_PI, M_PI)};
			}
			if (std::hypot(to.x - from.x, to.y - from.y) >= m_o.kidnap_min_distance) break;
		}
	m_legs.clear();
	goal = looped() ? m_loop[m_next % m_loop.size()] : nextGoal(to);
	return to;
}
}  // namespace vslam

#pragma once
/** \file SimulationEvents.h
 * The time-scheduled events of a rendered simulation, evaluated at a time:
 * lighting gain (changes and dark spells), camera blackouts, and where the
 * people walking through are.
 */
#include <libvslam/sim/TVisualSimOptions.h>

#include <Eigen/Core>
#include <optional>

namespace vslam
{
class SimulationEvents
{
   public:
	explicit SimulationEvents(const TVisualSimOptions& o) : m_o(o) {}

	/** Lighting relative to normal at time t (s from the start). */
	double lightingGain(double t) const
	{
		double gain = 1.0, since = -1;
		for (size_t i = 0; i + 1 < m_o.light_changes.size(); i += 2)
			if (m_o.light_changes[i] <= t && m_o.light_changes[i] >= since)
				since = m_o.light_changes[i], gain = m_o.light_changes[i + 1];
		return inside(m_o.dark_spells, t) ? gain * m_o.dark_gain : gain;
	}

	bool blackout(double t) const { return inside(m_o.blackouts, t); }

	size_t peopleCount() const { return m_o.people.size() / 6; }

	/** Person i's position at t, if walking then. */
	std::optional<Eigen::Vector2d> person(size_t i, double t) const
	{
		const double* p = &m_o.people[6 * i];
		const Eigen::Vector2d a(p[1], p[2]), b(p[3], p[4]);
		const double walked = (t - p[0]) * p[5], length = (b - a).norm();
		if (walked < 0 || walked > length) return std::nullopt;
		return length > 0 ? a + (b - a) * (walked / length) : a;
	}

   private:
	const TVisualSimOptions& m_o;

	static bool inside(const std::vector<double>& intervals, double t)
	{
		for (size_t i = 0; i + 1 < intervals.size(); i += 2)
			if (t >= intervals[i] && t < intervals[i + 1]) return true;
		return false;
	}
};
}  // namespace vslam

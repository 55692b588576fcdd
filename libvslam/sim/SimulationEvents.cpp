#include <libvslam/sim/SimulationEvents.h>
#include <mrpt/random/RandomGenerators.h>

namespace vslam
{
SimulationEvents::SimulationEvents(const CVisualSimulator::TOptions& o, const world::FreeSpace* freeSpace) : m_o(o)
{
	for (size_t i = 0; i + 5 < o.people.size(); i += 6)
		m_walks.push_back({o.people[i], {o.people[i + 1], o.people[i + 2]}, {o.people[i + 3], o.people[i + 4]}, o.people[i + 5]});
	if (!freeSpace || o.random_people == 0) return;
	// Their own generator: the robot's path does not change with them.
	mrpt::random::CRandomGenerator rng(o.seed * 2654435761u + 17);
	for (int k = 0; k < o.random_people; k++)
	{
		PersonWalk w;
		w.start = rng.drawUniform(0.05, 0.9) * o.duration;
		w.speed = rng.drawUniform(0.8, 1.3);
		w.from = freeSpace->freeCell(rng.drawUniform(0, 1));
		for (int attempt = 0; attempt < 200; attempt++)
		{
			w.to = freeSpace->freeCell(rng.drawUniform(0, 1));
			if ((w.to - w.from).norm() > 2.5 && freeSpace->segmentIsFree(w.from, w.to)) break;
		}
		m_walks.push_back(w);
	}
}

double SimulationEvents::lightingGain(double t) const
{
	double gain = 1.0, since = -1;
	for (size_t i = 0; i + 1 < m_o.light_changes.size(); i += 2)
		if (m_o.light_changes[i] <= t && m_o.light_changes[i] >= since)
			since = m_o.light_changes[i], gain = m_o.light_changes[i + 1];
	return inside(m_o.dark_spells, t) ? gain * m_o.dark_gain : gain;
}

int SimulationEvents::lightingEpoch(double t) const
{
	int epoch = 0;
	for (size_t i = 0; i + 1 < m_o.light_changes.size(); i += 2) epoch += m_o.light_changes[i] <= t;
	for (size_t i = 0; i + 1 < m_o.dark_spells.size(); i += 2) epoch += (m_o.dark_spells[i] <= t) + (m_o.dark_spells[i + 1] <= t);
	return epoch;
}

std::optional<Eigen::Vector2d> SimulationEvents::person(size_t i, double t) const
{
	const PersonWalk& w = m_walks.at(i);
	const double walked = (t - w.start) * w.speed, length = (w.to - w.from).norm();
	if (walked < 0 || walked > length) return std::nullopt;
	return length > 0 ? w.from + (w.to - w.from) * (walked / length) : w.from;
}

bool SimulationEvents::inside(const std::vector<double>& intervals, double t)
{
	for (size_t i = 0; i + 1 < intervals.size(); i += 2)
		if (t >= intervals[i] && t < intervals[i + 1]) return true;
	return false;
}
}  // namespace vslam

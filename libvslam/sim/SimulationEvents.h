#pragma once
/** \file SimulationEvents.h
 * The time-scheduled events of a rendered simulation, evaluated at a time:
 * lighting gain (changes and dark spells), camera blackouts, and where the
 * people walking through are (the walks the INI lists, and random walks
 * between free places of the home, drawn from the seed).
 */
#include <libvslam/sim/CVisualSimulator.h>
#include <libvslam/world/FreeSpace.h>

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace vslam
{
/** A person appears at `from` at time `start` and walks to `to`. */
struct PersonWalk
{
	double start = 0;
	Eigen::Vector2d from{0, 0}, to{0, 0};
	double speed = 1;
};

class SimulationEvents
{
   public:
	/** freeSpace: where random walks may go (nullptr: none are drawn). */
	SimulationEvents(const CVisualSimulator::TOptions& o, const world::FreeSpace* freeSpace);

	/** Lighting relative to normal at time t (s from the start). */
	double lightingGain(double t) const;
	/** How many lighting changes happened by t (a new white balance each). */
	int lightingEpoch(double t) const;
	bool blackout(double t) const { return inside(m_o.blackouts, t); }

	size_t peopleCount() const { return m_walks.size(); }
	const PersonWalk& walk(size_t i) const { return m_walks.at(i); }
	/** Person i's position at t, if walking then. */
	std::optional<Eigen::Vector2d> person(size_t i, double t) const;

   private:
	const CVisualSimulator::TOptions& m_o;
	std::vector<PersonWalk> m_walks;

	static bool inside(const std::vector<double>& intervals, double t);
};
}  // namespace vslam

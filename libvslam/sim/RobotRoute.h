#pragma once
/** \file RobotRoute.h
 * Where the simulated robot drives next, for each kind of path: the listed
 * waypoint loop, random goals in straight sight, a systematic tour through
 * every room (looped), or roaming to random goals anywhere by planned
 * paths. Also where a kidnapped robot is put: a pose it had before (a
 * place its map knows) or any free pose.
 */
#include <libvslam/models/SE2.h>
#include <libvslam/sim/CVisualSimulator.h>
#include <libvslam/world/FreeSpace.h>
#include <libvslam/world/PathPlanner.h>
#include <mrpt/random/RandomGenerators.h>

#include <deque>
#include <vector>

namespace vslam
{
class RobotRoute
{
   public:
	RobotRoute(const CVisualSimulator::TOptions& o, const world::FreeSpace& freeSpace, mrpt::random::CRandomGenerator& rng);

	/** Where the robot starts and the first goal. */
	se2::Pose start() const { return m_start; }
	Eigen::Vector2d firstGoal();
	/** The next goal on arrival at the current one, from pose p. */
	Eigen::Vector2d nextGoal(const se2::Pose& p);
	/** Loops completed (waypoints and tours). */
	int laps() const { return m_laps; }
	/** The loop's points (waypoints and tours), empty otherwise. */
	const std::vector<Eigen::Vector2d>& loop() const { return m_loop; }

	/** Remembers the true pose of a step (for kidnaps to visited places). */
	void record(const se2::Pose& p);
	/** The pose a kidnap at `from` puts the robot at; the route goes on
	 * from there (its next goal is returned in `goal`). */
	se2::Pose kidnap(const se2::Pose& from, Eigen::Vector2d& goal);

   private:
	const CVisualSimulator::TOptions& m_o;
	const world::FreeSpace& m_free;
	mrpt::random::CRandomGenerator& m_rng;
	world::PathPlanner m_planner;
	std::vector<Eigen::Vector2d> m_loop;
	size_t m_next = 1;  //!< index of the loop point driven to
	int m_laps = 0;
	std::deque<Eigen::Vector2d> m_legs;  //!< roam: the planned path's corners still ahead
	se2::Pose m_start;
	struct Visit
	{
		se2::Pose pose;
		size_t next;
	};
	std::vector<Visit> m_visits;

	bool looped() const { return !m_loop.empty(); }
	Eigen::Vector2d goalInSight(const se2::Pose& from);
	Eigen::Vector2d roamGoal(const se2::Pose& from);
};
}  // namespace vslam

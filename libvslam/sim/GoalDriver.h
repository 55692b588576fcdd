#pragma once
/** \file GoalDriver.h
 * The simulated robot's driver: a differential-drive robot heading for a
 * goal point turns in place while the goal is far off its heading, else
 * drives forward at constant speed and steers; on arrival it asks for the
 * next goal. Shared by both simulators.
 */
#include <libvslam/models/SE2.h>

#include <functional>

namespace vslam
{
struct TDriveOptions
{
	double speed = 0.15;  //!< m/s
	double maxTurnRate = 0.5;  //!< rad/s
	double dt = 0.1;  //!< s, one step
	double turnInPlaceAbove = 0.5;  //!< rad of heading error
	double goalTolerance = 0.1;  //!< m
};

class GoalDriver
{
   public:
	/** Called on arrival at the current goal, with the current pose. */
	using NextGoal = std::function<Eigen::Vector2d(const se2::Pose&)>;

	GoalDriver(const TDriveOptions& limits, NextGoal nextGoal) : m_limits(limits), m_nextGoal(std::move(nextGoal)) {}

	void setGoal(const Eigen::Vector2d& goal) { m_goal = goal; }
	const Eigen::Vector2d& goal() const { return m_goal; }

	/** The true motion increment (robot frame) for one step from pose p. */
	se2::Pose step(const se2::Pose& p)
	{
		if (std::hypot(m_goal[0] - p.x, m_goal[1] - p.y) < m_limits.goalTolerance) m_goal = m_nextGoal(p);
		const double err = se2::wrap(std::atan2(m_goal[1] - p.y, m_goal[0] - p.x) - p.phi);
		const double maxTurn = m_limits.maxTurnRate * m_limits.dt;
		const double turn = std::clamp(err, -maxTurn, maxTurn);
		const double forward =
			std::abs(err) > m_limits.turnInPlaceAbove ? 0.0 : m_limits.speed * m_limits.dt * std::cos(err);
		return {forward, 0, turn};
	}

   private:
	TDriveOptions m_limits;
	NextGoal m_nextGoal;
	Eigen::Vector2d m_goal{0, 0};
};
}  // namespace vslam

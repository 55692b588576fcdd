#pragma once
/** \file PathPlanner.h
 * Paths through a home's free space for the simulated robot: the shortest
 * way between two free points on the free-space grid, kept away from
 * obstacles where there is room (a robot drives through the middle of a
 * doorway, not along its frame), then cut into the fewest straight legs
 * the free space allows.
 */
#include <libvslam/world/FreeSpace.h>

#include <Eigen/Core>
#include <vector>

namespace vslam::world
{
class PathPlanner
{
   public:
	explicit PathPlanner(const FreeSpace& freeSpace);

	/** The corners of a collision-free path from a to b, b included and a
	 * not; empty if b cannot be reached from a. */
	std::vector<Eigen::Vector2d> plan(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;

	/** Path length (m) from `from` to every grid cell (infinite where
	 * unreachable), row-major over FreeSpace::reachableMask(). */
	std::vector<double> distancesFrom(const Eigen::Vector2d& from) const;

	/** Clearance beyond the robot's radius of every cell (m). */
	const cv::Mat& margin() const { return m_margin; }

	/** The cell (row, col) of a point, or false outside the grid. */
	bool cellOf(const Eigen::Vector2d& p, int& row, int& col) const;
	Eigen::Vector2d centreOf(int row, int col) const;

   private:
	const FreeSpace& m_free;
	cv::Mat m_margin;  //!< CV_32F

	std::vector<double> dijkstra(int row, int col, std::vector<int>* parent) const;
};

/** A systematic loop through every room: stops at the places of largest
 * clearance (room centres, hall junctions) at least `spacing` apart,
 * visited in a short order from the one nearest `start`, joined by planned
 * legs and closed back to the first stop. The waypoints start at `start`. */
std::vector<Eigen::Vector2d> homeTour(const FreeSpace& freeSpace, const Eigen::Vector2d& start, double spacing = 2.5);
}  // namespace vslam::world

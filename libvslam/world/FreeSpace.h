#pragma once
/** \file FreeSpace.h
 * Where a round robot of a given radius can be: a grid over the floor plan
 * (cells whose centre is at least the radius from every obstacle outline),
 * restricted to the region reachable from a start point by a flood fill,
 * so random goals and kidnap targets are never outside the building or
 * inside furniture. Also checks straight drives for collisions.
 */
#include <libvslam/world/FloorPlan.h>
#include <opencv2/core.hpp>

namespace vslam::world
{
class FreeSpace
{
   public:
	/** Throws InputError (naming the world file) if `start` is not free. */
	FreeSpace(const FloorPlan& plan, double robotRadius, const Eigen::Vector2d& start, double resolution = 0.05);

	/** Inside the reachable region, clear of obstacles. */
	bool isFree(const Eigen::Vector2d& p) const;
	/** A straight drive from a to b keeps clear of every obstacle and
	 * stays in the reachable region. */
	bool segmentIsFree(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
	/** Distance from p to the nearest obstacle outline (0 inside one). */
	double clearance(const Eigen::Vector2d& p) const;
	/** The obstacle segment a drive from a to b crosses or comes too close
	 * to, or nullptr. */
	const Segment* blockingSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;

	/** Area of the reachable region, m^2. */
	double freeArea() const;
	/** The centre of a free cell, chosen by u in [0, 1) (uniform u: uniform cell). */
	Eigen::Vector2d freeCell(double u) const;

	/** Grid geometry, for drawing: cell (row, col) centre is
	 * origin + ((col + 0.5) * res, (row + 0.5) * res). */
	const cv::Mat& reachableMask() const { return m_reachable; }
	Eigen::Vector2d origin() const { return m_origin; }
	double resolution() const { return m_res; }

   private:
	std::vector<Segment> m_segments;
	std::vector<std::vector<Eigen::Vector2d>> m_solids;
	double m_radius, m_res;
	Eigen::Vector2d m_origin;
	cv::Mat m_reachable;  //!< CV_8U, 255 where reachable and free
	std::vector<cv::Point> m_freeCells;
	bool cellOf(const Eigen::Vector2d& p, int& row, int& col) const;
};

/** Distance from point p to segment [a, b]. */
double pointSegmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b);
/** Distance between segments [a, b] and [c, d] (0 if they cross). */
double segmentSegmentDistance(
	const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, const Eigen::Vector2d& d);
}  // namespace vslam::world

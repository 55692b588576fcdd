#include <libvslam/core/InputError.h>
#include <libvslam/world/FreeSpace.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace vslam::world
{
double pointSegmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
	const Eigen::Vector2d ab = b - a;
	const double len2 = ab.squaredNorm();
	const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
	return (p - (a + t * ab)).norm();
}

namespace
{
double cross(const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u[0] * v[1] - u[1] * v[0]; }
}  // namespace

double segmentSegmentDistance(
	const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, const Eigen::Vector2d& d)
{
	const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
	const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
	if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
		return 0;
	return std::min(
		{pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d), pointSegmentDistance(c, a, b),
		 pointSegmentDistance(d, a, b)});
}

FreeSpace::FreeSpace(const FloorPlan& plan, double robotRadius, const Eigen::Vector2d& start, double resolution)
	: m_segments(plan.obstacleSegments()), m_solids(plan.solidPolygons()), m_radius(robotRadius), m_res(resolution)
{
	const auto [lo, hi] = plan.bounds();
	m_origin = lo - Eigen::Vector2d(1, 1);
	const int cols = static_cast<int>(std::ceil((hi[0] - lo[0] + 2) / m_res));
	const int rows = static_cast<int>(std::ceil((hi[1] - lo[1] + 2) / m_res));
	if (static_cast<double>(cols) * rows > 1e7)
		throw InputError("world file '" + plan.sourceFile + "': the world is too large (over 25,000 m^2 at 5 cm)");
	// Clearance of every cell centre by a distance transform of the
	// rasterized obstacles (linear in the cells, whatever the number of
	// obstacles); exact distances are used for single queries (isFree).
	cv::Mat obstacles(rows, cols, CV_8U, cv::Scalar(255));
	const auto cell = [&](const Eigen::Vector2d& p) {
		return cv::Point(static_cast<int>(std::floor((p[0] - m_origin[0]) / m_res)),
			static_cast<int>(std::floor((p[1] - m_origin[1]) / m_res)));
	};
	for (const Segment& s : m_segments) cv::line(obstacles, cell(s.a), cell(s.b), cv::Scalar(0), 1, cv::LINE_8);
	for (const auto& solid : m_solids)
	{
		std::vector<cv::Point> pts;
		for (const auto& c : solid) pts.push_back(cell(c));
		cv::fillConvexPoly(obstacles, pts, cv::Scalar(0));
	}
	cv::Mat distance;
	cv::distanceTransform(obstacles, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
	// The rasterized distance is within a cell diagonal of the exact one:
	// cells near the limit get the exact clearance.
	cv::Mat freeCells(rows, cols, CV_8U, cv::Scalar(0));
	for (int r = 0; r < rows; r++)
		for (int c = 0; c < cols; c++)
		{
			const double d = distance.at<float>(r, c) * m_res;
			if (d >= m_radius + 1.5 * m_res ||
				(d > m_radius - 1.5 * m_res &&
					clearance(m_origin + Eigen::Vector2d((c + 0.5) * m_res, (r + 0.5) * m_res)) >= m_radius))
				freeCells.at<uchar>(r, c) = 255;
		}
	m_reachable = freeCells;  // cellOf() reads the grid size
	int sr = 0, sc = 0;
	if (!cellOf(start, sr, sc) || !freeCells.at<uchar>(sr, sc))
		throw InputError(
			"world file '" + plan.sourceFile + "': the start position (" + std::to_string(start[0]) + ", " +
			std::to_string(start[1]) + ") is not free for a robot of radius " + std::to_string(m_radius) + " m");
	cv::Mat mask(rows + 2, cols + 2, CV_8U, cv::Scalar(0));
	cv::Mat work = freeCells.clone();
	cv::floodFill(work, mask, cv::Point(sc, sr), cv::Scalar(128), nullptr, cv::Scalar(0), cv::Scalar(0), 4);
	m_reachable = cv::Mat(rows, cols, CV_8U, cv::Scalar(0));
	m_reachable.setTo(255, work == 128);
	cv::findNonZero(m_reachable, m_freeCells);
	// A region touching the grid border is outside the building.
	for (const cv::Point& p : m_freeCells)
		if (p.x == 0 || p.y == 0 || p.x == cols - 1 || p.y == rows - 1)
			throw InputError(
				"world file '" + plan.sourceFile +
				"': the walls around the start position are not closed (the robot could leave the building)");
}

bool FreeSpace::cellOf(const Eigen::Vector2d& p, int& row, int& col) const
{
	if (!std::isfinite(p[0]) || !std::isfinite(p[1])) return false;
	const double c = std::floor((p[0] - m_origin[0]) / m_res), r = std::floor((p[1] - m_origin[1]) / m_res);
	if (c < 0 || r < 0 || c >= m_reachable.cols || r >= m_reachable.rows) return false;
	row = static_cast<int>(r), col = static_cast<int>(c);
	return true;
}

double FreeSpace::clearance(const Eigen::Vector2d& p) const
{
	for (const auto& solid : m_solids)
		if (insideConvex(solid, p)) return 0;
	double d = std::numeric_limits<double>::infinity();
	for (const Segment& s : m_segments) d = std::min(d, pointSegmentDistance(p, s.a, s.b));
	return d;
}

bool FreeSpace::isFree(const Eigen::Vector2d& p) const
{
	int r = 0, c = 0;
	return cellOf(p, r, c) && m_reachable.at<uchar>(r, c) && clearance(p) >= m_radius;
}

const Segment* FreeSpace::blockingSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const
{
	for (const Segment& s : m_segments)
		if (segmentSegmentDistance(a, b, s.a, s.b) < m_radius) return &s;
	return nullptr;
}

bool FreeSpace::segmentIsFree(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const
{
	return isFree(a) && isFree(b) && blockingSegment(a, b) == nullptr;
}

double FreeSpace::freeArea() const { return m_freeCells.size() * m_res * m_res; }

Eigen::Vector2d FreeSpace::freeCell(double u) const
{
	const size_t i = std::min(m_freeCells.size() - 1, static_cast<size_t>(u * m_freeCells.size()));
	const cv::Point& p = m_freeCells[i];
	return m_origin + Eigen::Vector2d((p.x + 0.5) * m_res, (p.y + 0.5) * m_res);
}
}  // namespace vslam::world

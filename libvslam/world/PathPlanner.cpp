#include <libvslam/world/PathPlanner.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace vslam::world
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();

/** Extra cost per metre near obstacles: a path 10 cm from them costs
 * three times its length, one 50 cm away barely more. */
double proximityCost(double margin) { return 1.0 + 0.2 / std::max(0.1, margin); }
}  // namespace

PathPlanner::PathPlanner(const FreeSpace& freeSpace) : m_free(freeSpace)
{
	cv::distanceTransform(m_free.reachableMask(), m_margin, cv::DIST_L2, cv::DIST_MASK_PRECISE);
	m_margin *= m_free.resolution();
}

bool PathPlanner::cellOf(const Eigen::Vector2d& p, int& row, int& col) const
{
	const Eigen::Vector2d q = (p - m_free.origin()) / m_free.resolution();
	if (!std::isfinite(q[0]) || !std::isfinite(q[1])) return false;
	col = static_cast<int>(std::floor(q[0])), row = static_cast<int>(std::floor(q[1]));
	return row >= 0 && col >= 0 && row < m_margin.rows && col < m_margin.cols;
}

Eigen::Vector2d PathPlanner::centreOf(int row, int col) const
{
	return m_free.origin() + Eigen::Vector2d((col + 0.5) * m_free.resolution(), (row + 0.5) * m_free.resolution());
}

std::vector<double> PathPlanner::dijkstra(int row, int col, std::vector<int>* parent) const
{
	const int rows = m_margin.rows, cols = m_margin.cols;
	std::vector<double> dist(static_cast<size_t>(rows) * cols, kInf);
	if (parent) parent->assign(dist.size(), -1);
	const cv::Mat& mask = m_free.reachableMask();
	using Item = std::pair<double, int>;
	std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
	dist[static_cast<size_t>(row) * cols + col] = 0;
	open.push({0, row * cols + col});
	const double res = m_free.resolution();
	while (!open.empty())
	{
		const auto [d, i] = open.top();
		open.pop();
		if (d > dist[static_cast<size_t>(i)]) continue;
		const int r = i / cols, c = i % cols;
		for (int dr = -1; dr <= 1; dr++)
			for (int dc = -1; dc <= 1; dc++)
			{
				const int nr = r + dr, nc = c + dc;
				if ((dr == 0 && dc == 0) || nr < 0 || nc < 0 || nr >= rows || nc >= cols || !mask.at<uchar>(nr, nc)) continue;
				const double step = res * std::hypot(dr, dc) * proximityCost(m_margin.at<float>(nr, nc));
				const size_t j = static_cast<size_t>(nr) * cols + nc;
				if (d + step < dist[j])
				{
					dist[j] = d + step;
					if (parent) (*parent)[j] = i;
					open.push({dist[j], static_cast<int>(j)});
				}
			}
	}
	return dist;
}

std::vector<double> PathPlanner::distancesFrom(const Eigen::Vector2d& from) const
{
	int r = 0, c = 0;
	if (!cellOf(from, r, c) || !m_free.isFree(from)) return std::vector<double>(m_margin.total(), kInf);
	return dijkstra(r, c, nullptr);
}

std::vector<Eigen::Vector2d> PathPlanner::plan(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const
{
	int ra = 0, ca = 0, rb = 0, cb = 0;
	if (!cellOf(a, ra, ca) || !cellOf(b, rb, cb) || !m_free.isFree(b)) return {};
	std::vector<int> parent;
	const std::vector<double> dist = dijkstra(ra, ca, &parent);
	const int cols = m_margin.cols;
	if (!std::isfinite(dist[static_cast<size_t>(rb) * cols + cb])) return {};
	std::vector<Eigen::Vector2d> cells;  // from b back to a
	for (int i = rb * cols + cb; i >= 0 && i != ra * cols + ca; i = parent[static_cast<size_t>(i)])
		cells.push_back(centreOf(i / cols, i % cols));
	std::reverse(cells.begin(), cells.end());
	if (cells.empty()) return {b};  // in a's cell
	cells.back() = b;
	// The fewest straight legs: from each corner, the farthest cell in free sight.
	std::vector<Eigen::Vector2d> legs;
	Eigen::Vector2d from = a;
	size_t k = 0;
	while (k < cells.size())
	{
		size_t far = k;
		for (size_t j = cells.size(); j-- > k;)
			if (m_free.segmentIsFree(from, cells[j])) { far = j; break; }
		legs.push_back(cells[far]);
		from = cells[far];
		k = far + 1;
	}
	return legs;
}

std::vector<Eigen::Vector2d> homeTour(const FreeSpace& freeSpace, const Eigen::Vector2d& start, double spacing)
{
	const PathPlanner planner(freeSpace);
	// Stops: the largest clearances, each at least `spacing` from the others.
	cv::Mat margin = planner.margin().clone();
	std::vector<Eigen::Vector2d> stops;
	for (;;)
	{
		double best = 0;
		cv::Point at;
		cv::minMaxLoc(margin, nullptr, &best, nullptr, &at);
		if (best < 0.25) break;
		stops.push_back(planner.centreOf(at.y, at.x));
		cv::circle(margin, at, static_cast<int>(spacing / freeSpace.resolution()), cv::Scalar(0), -1);
	}
	if (stops.empty()) return {start};
	// A short loop: nearest unvisited stop (by path length) from the start.
	std::vector<Eigen::Vector2d> order;
	Eigen::Vector2d at = start;
	while (!stops.empty())
	{
		const std::vector<double> d = planner.distancesFrom(at);
		size_t best = 0;
		double bestD = kInf;
		for (size_t i = 0; i < stops.size(); i++)
		{
			int r = 0, c = 0;
			planner.cellOf(stops[i], r, c);
			const double di = d[static_cast<size_t>(r) * planner.margin().cols + c];
			if (di < bestD) bestD = di, best = i;
		}
		if (!std::isfinite(bestD)) break;
		order.push_back(stops[best]);
		at = stops[best];
		stops.erase(stops.begin() + static_cast<long>(best));
	}
	std::vector<Eigen::Vector2d> tour{start};
	order.push_back(start);
	for (const Eigen::Vector2d& stop : order)
	{
		const auto legs = planner.plan(tour.back(), stop);
		tour.insert(tour.end(), legs.begin(), legs.end());
	}
	return tour;
}
}  // namespace vslam::world

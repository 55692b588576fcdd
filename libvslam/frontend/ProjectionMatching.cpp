#include <libvslam/frontend/ProjectionMatching.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

using namespace vslam;

namespace
{
/** The features bucketed in square cells of the search radius: a window
 * around a pixel lies within the 3 x 3 cells around the pixel's cell. */
class FeatureGrid
{
   public:
	FeatureGrid(const std::vector<cv::Point2f>& pixels, const std::vector<bool>& taken, double cellSize)
		: m_cell(cellSize)
	{
		for (const auto& p : pixels)
		{
			m_x0 = std::min(m_x0, p.x);
			m_y0 = std::min(m_y0, p.y);
			m_x1 = std::max(m_x1, p.x);
			m_y1 = std::max(m_y1, p.y);
		}
		if (pixels.empty()) return;
		m_cols = cellOf(m_x1, m_x0) + 1;
		m_rows = cellOf(m_y1, m_y0) + 1;
		m_cells.resize(static_cast<size_t>(m_cols) * m_rows);
		for (size_t i = 0; i < pixels.size(); i++)
			if (!taken[i])
				m_cells[static_cast<size_t>(cellOf(pixels[i].y, m_y0)) * m_cols + cellOf(pixels[i].x, m_x0)]
					.push_back(static_cast<int>(i));
	}

	/** Calls visit(feature) for each untaken feature in the 3 x 3 cells
	 * around `p`. */
	template <typename Visit>
	void forEachNear(const cv::Point2f& p, Visit&& visit) const
	{
		if (m_cells.empty() || !(p.x >= m_x0 - m_cell && p.x <= m_x1 + m_cell && p.y >= m_y0 - m_cell &&
								 p.y <= m_y1 + m_cell))
			return;
		const int cx = cellOf(p.x, m_x0), cy = cellOf(p.y, m_y0);
		for (int y = std::max(0, cy - 1); y <= std::min(m_rows - 1, cy + 1); y++)
			for (int x = std::max(0, cx - 1); x <= std::min(m_cols - 1, cx + 1); x++)
				for (int i : m_cells[static_cast<size_t>(y) * m_cols + x]) visit(i);
	}

   private:
	int cellOf(float v, float origin) const { return static_cast<int>(std::floor((v - origin) / m_cell)); }

	double m_cell;
	float m_x0 = std::numeric_limits<float>::max(), m_y0 = m_x0;
	float m_x1 = std::numeric_limits<float>::lowest(), m_y1 = m_x1;
	int m_cols = 0, m_rows = 0;
	std::vector<std::vector<int>> m_cells;
};
}  // namespace

std::vector<std::pair<int, int>> vslam::matchByProjection(const std::vector<cv::Point2f>& projected,
	const std::vector<bool>& projectedValid, const cv::Mat& pointDescriptors, const std::vector<bool>& pointTaken,
	const std::vector<cv::Point2f>& featurePixels, const cv::Mat& featureDescriptors,
	const std::vector<bool>& featureTaken, const ProjectionMatchLimits& limits)
{
	const size_t points = projected.size(), features = featurePixels.size();
	if (projectedValid.size() != points || pointTaken.size() != points ||
		static_cast<size_t>(pointDescriptors.rows) != points || featureTaken.size() != features ||
		static_cast<size_t>(featureDescriptors.rows) != features)
		throw std::invalid_argument("matchByProjection: inconsistent sizes");
	std::vector<std::pair<int, int>> out;
	if (points == 0 || features == 0 || !(limits.radiusPx > 0)) return out;
	if (pointDescriptors.type() != CV_32F || featureDescriptors.type() != CV_32F ||
		pointDescriptors.cols != featureDescriptors.cols)
		throw std::invalid_argument("matchByProjection: needs CV_32F descriptors of the same length");

	const FeatureGrid grid(featurePixels, featureTaken, limits.radiusPx);
	const double r2 = limits.radiusPx * limits.radiusPx;
	// For each feature: the distance and row of its nearest matched point.
	std::vector<std::pair<double, int>> bestForFeature(features, {0.0, -1});
	for (size_t j = 0; j < points; j++)
	{
		if (!projectedValid[j] || pointTaken[j]) continue;
		const cv::Point2f& p = projected[j];
		double d1 = std::numeric_limits<double>::infinity(), d2 = d1;
		int nearest = -1;
		grid.forEachNear(p, [&](int i) {
			const cv::Point2f& f = featurePixels[i];
			if ((f.x - p.x) * (f.x - p.x) + (f.y - p.y) * (f.y - p.y) > r2) return;
			const double d = cv::norm(pointDescriptors.row(static_cast<int>(j)), featureDescriptors.row(i), cv::NORM_L2);
			if (d < d1)
			{
				d2 = d1;
				d1 = d;
				nearest = i;
			}
			else if (d < d2)
				d2 = d;
		});
		if (nearest < 0 || d1 > limits.maxDistance || !(d1 < limits.ratio * d2)) continue;
		auto& best = bestForFeature[nearest];
		if (best.second < 0 || d1 < best.first) best = {d1, static_cast<int>(j)};
	}
	for (size_t i = 0; i < features; i++)
		if (bestForFeature[i].second >= 0) out.emplace_back(static_cast<int>(i), bestForFeature[i].second);
	std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
	return out;
}

#include <libvslam/frontend/BestBinFirstTree.h>

#include <numeric>
#include <stdexcept>

using namespace vslam;

namespace
{
/** Rows sampled (evenly through the cell) to choose a split dimension. */
constexpr int32_t kSpreadSample = 64;
}  // namespace

BestBinFirstTree::BestBinFirstTree(const cv::Mat& rows, float unit) : m_rows(rows), m_dims(rows.cols), m_unit(unit)
{
	if ((rows.type() != CV_32F && rows.type() != CV_8S) || rows.rows < 1)
		throw std::invalid_argument("BestBinFirstTree: needs at least one CV_32F or CV_8S row");
	m_order.resize(static_cast<size_t>(rows.rows));
	std::iota(m_order.begin(), m_order.end(), 0);
	m_nodes.reserve(2 * m_order.size() / kLeafSize + 1);
	build(0, rows.rows);  // reads the input rows through m_order
	m_rows = cv::Mat(rows.rows, rows.cols, rows.type());
	for (int i = 0; i < rows.rows; i++) rows.row(m_order[i]).copyTo(m_rows.row(i));
}

cv::Mat BestBinFirstTree::rowsInInputOrder() const
{
	cv::Mat out(m_rows.rows, m_rows.cols, m_rows.type());
	for (int i = 0; i < m_rows.rows; i++) m_rows.row(i).copyTo(out.row(m_order[i]));
	return out;
}

int32_t BestBinFirstTree::build(int32_t begin, int32_t end)
{
	const auto node = static_cast<int32_t>(m_nodes.size());
	m_nodes.push_back({-1, 0.f, 0, begin, end});
	if (end - begin <= kLeafSize) return node;

	// The dimension along which the cell's rows spread most (variance).
	const int32_t step = std::max<int32_t>(1, (end - begin) / kSpreadSample);
	Eigen::VectorXd sum = Eigen::VectorXd::Zero(m_dims), sumSq = Eigen::VectorXd::Zero(m_dims);
	int sampled = 0;
	for (int32_t i = begin; i < end; i += step, sampled++)
	{
		for (int d = 0; d < m_dims; d++)
		{
			const double v = value(m_order[i], d);
			sum[d] += v;
			sumSq[d] += v * v;
		}
	}
	Eigen::Index dim = 0;
	(sumSq - sum.cwiseProduct(sum) / sampled).maxCoeff(&dim);

	// Split at the median: rows [begin, middle) at or below it, the rest at
	// or above.
	const int32_t middle = begin + (end - begin) / 2;
	const int splitDim = static_cast<int>(dim);
	std::nth_element(m_order.begin() + begin, m_order.begin() + middle, m_order.begin() + end,
		[&](int32_t a, int32_t b) { return value(a, splitDim) < value(b, splitDim); });
	const float split = value(m_order[middle], splitDim);

	build(begin, middle);
	const int32_t right = build(middle, end);
	m_nodes[node] = {static_cast<int32_t>(dim), split, right, begin, end};
	return node;
}

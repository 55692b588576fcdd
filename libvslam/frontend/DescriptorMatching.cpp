#include <libvslam/frontend/DescriptorMatching.h>

#include <Eigen/Core>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace
{
using RowMajorFloats = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using ConstRows = Eigen::Map<const RowMajorFloats>;

/** Rows of `a` per matrix product: bounds the distance block's memory. */
constexpr int kRowsPerBlock = 256;

ConstRows asEigen(const cv::Mat& m) { return ConstRows(m.ptr<float>(), m.rows, m.cols); }

/** The two nearest rows of `b` (j1 nearest) by the ranking scores
 * |b_j|^2 - 2 a.b_j of one row of the product. */
std::pair<int, int> twoNearest(const float* dotsRow, const Eigen::VectorXf& bNorms)
{
	float s1 = std::numeric_limits<float>::infinity(), s2 = s1;
	int j1 = 0, j2 = 1;
	for (int j = 0; j < bNorms.size(); j++)
	{
		const float s = bNorms[j] - 2 * dotsRow[j];
		if (s < s1)
		{
			s2 = s1;
			j2 = j1;
			s1 = s;
			j1 = j;
		}
		else if (s < s2)
		{
			s2 = s;
			j2 = j;
		}
	}
	return {j1, j2};
}
}  // namespace

std::vector<std::pair<int, int>> vslam::matchDescriptors(const cv::Mat& a, const cv::Mat& b, double ratio)
{
	std::vector<std::pair<int, int>> out;
	if (a.rows == 0 || b.rows < 2) return out;
	if (a.type() != CV_32F || b.type() != CV_32F || a.cols != b.cols)
		throw std::invalid_argument("matchDescriptors: needs CV_32F descriptors of the same length");
	const cv::Mat ac = a.isContinuous() ? a : a.clone(), bc = b.isContinuous() ? b : b.clone();
	const ConstRows A = asEigen(ac), B = asEigen(bc);
	const Eigen::VectorXf bNorms = B.rowwise().squaredNorm();

	// For each row of b: the distance and row of its best a so far.
	std::vector<std::pair<float, int>> bestForB(b.rows, {0.f, -1});
	RowMajorFloats dots;
	for (int start = 0; start < a.rows; start += kRowsPerBlock)
	{
		const int n = std::min(kRowsPerBlock, a.rows - start);
		dots.noalias() = A.middleRows(start, n) * B.transpose();
		for (int i = 0; i < n; i++)
		{
			const int ai = start + i;
			auto [j1, j2] = twoNearest(dots.row(i).data(), bNorms);
			float d1 = (A.row(ai) - B.row(j1)).norm(), d2 = (A.row(ai) - B.row(j2)).norm();
			if (d2 < d1)
			{
				std::swap(d1, d2);
				std::swap(j1, j2);
			}
			if (!(d1 < ratio * d2)) continue;
			auto& best = bestForB[j1];
			if (best.second < 0 || d1 < best.first) best = {d1, ai};
		}
	}
	for (int j = 0; j < b.rows; j++)
		if (bestForB[j].second >= 0)
			out.emplace_back(bestForB[j].second, j);
	return out;
}

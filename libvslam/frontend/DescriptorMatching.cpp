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
 * |b_j|^2 - 2 a.b_j of one row of the product, among the rows `allowed`
 * lets row `ai` of a match (all if none); -1 where there is none. */
std::pair<int, int> twoNearest(
	const float* dotsRow, const Eigen::VectorXf& bNorms, int ai, const vslam::MatchFilter* allowed)
{
	float s1 = std::numeric_limits<float>::infinity(), s2 = s1;
	int j1 = allowed ? -1 : 0, j2 = allowed ? -1 : 1;
	for (int j = 0; j < bNorms.size(); j++)
	{
		if (allowed && !(*allowed)(ai, j)) continue;
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

/** For each row of b, its two nearest rows of a so far, by the ranking
 * scores |a_i|^2 - 2 a_i.b_j (b's side of the ratio test). */
class NearestOfB
{
   public:
	explicit NearestOfB(int rowsB) : m_nearest(rowsB) {}

	/** Row `ai` of a with its row `dotsRow` of the product a.b^T. */
	void add(const float* dotsRow, float aNorm, int ai, const vslam::MatchFilter* allowed)
	{
		for (size_t j = 0; j < m_nearest.size(); j++)
		{
			if (allowed && !(*allowed)(ai, static_cast<int>(j))) continue;
			const float s = aNorm - 2 * dotsRow[j];
			Two& n = m_nearest[j];
			if (s < n.s1)
			{
				n.s2 = n.s1;
				n.i2 = n.i1;
				n.s1 = s;
				n.i1 = ai;
			}
			else if (s < n.s2)
			{
				n.s2 = s;
				n.i2 = ai;
			}
		}
	}

	/** Whether row `ai` of a is row `bj`'s nearest and passes the ratio
	 * test, by distances measured directly. */
	bool passes(const ConstRows& A, const ConstRows& B, int ai, int bj, double ratio) const
	{
		const Two& n = m_nearest[bj];
		if (n.i2 < 0) return false;  // no second candidate: no ratio test
		float e1 = (A.row(n.i1) - B.row(bj)).norm(), e2 = (A.row(n.i2) - B.row(bj)).norm();
		int nearest = n.i1;
		if (e2 < e1)
		{
			std::swap(e1, e2);
			nearest = n.i2;
		}
		return nearest == ai && e1 < ratio * e2;
	}

   private:
	struct Two
	{
		float s1 = std::numeric_limits<float>::infinity(), s2 = std::numeric_limits<float>::infinity();
		int i1 = -1, i2 = -1;
	};
	std::vector<Two> m_nearest;
};
}  // namespace

std::vector<std::pair<int, int>> vslam::matchDescriptors(const cv::Mat& a, const cv::Mat& b, double ratio)
{
	return matchDescriptors(a, b, ratio, nullptr);
}

std::vector<std::pair<int, int>> vslam::matchDescriptors(
	const cv::Mat& a, const cv::Mat& b, double ratio, const MatchFilter* allowed, bool bothWays)
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
	NearestOfB nearestOfB(bothWays ? b.rows : 0);
	const Eigen::VectorXf aNorms = bothWays ? Eigen::VectorXf(A.rowwise().squaredNorm()) : Eigen::VectorXf();
	RowMajorFloats dots;
	for (int start = 0; start < a.rows; start += kRowsPerBlock)
	{
		const int n = std::min(kRowsPerBlock, a.rows - start);
		dots.noalias() = A.middleRows(start, n) * B.transpose();
		for (int i = 0; i < n; i++)
		{
			const int ai = start + i;
			if (bothWays) nearestOfB.add(dots.row(i).data(), aNorms[ai], ai, allowed);
			auto [j1, j2] = twoNearest(dots.row(i).data(), bNorms, ai, allowed);
			if (j2 < 0) continue;  // no second candidate: no ratio test
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
		if (bestForB[j].second >= 0 && (!bothWays || nearestOfB.passes(A, B, bestForB[j].second, j, ratio)))
			out.emplace_back(bestForB[j].second, j);
	return out;
}

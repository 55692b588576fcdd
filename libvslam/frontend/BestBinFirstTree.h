#pragma once
/** \file BestBinFirstTree.h
 * A static k-d tree over a block of descriptor codes, searched best bin
 * first (Beis and Lowe 1997) with a budget of rows compared per query.
 *
 * Rows are split at the median of the dimension of largest spread until a
 * leaf holds at most kLeafSize rows; a leaf's rows are compared together,
 * so a query pays one descent per kLeafSize rows, not one per row as in
 * FLANN's k-d tree. The branches not taken wait in a priority queue keyed
 * by the exact distance from the query to their cell (the incremental
 * distance of Arya and Mount: one offset per dimension, kept as a chain of
 * changes), so the search is
 * exact when the budget covers every row, and otherwise visits cells
 * nearest first until the budget is spent.
 *
 * The tree keeps its own copy of the rows, leaf by leaf, so a leaf's rows
 * are read from one block of memory. Rows may be given as floats or as
 * signed-byte codes standing for `unit` x code (the projected descriptor
 * codes of DescriptorCodec.h): a quarter of the memory, and for codes of
 * up to 64 dimensions with a power-of-two unit, and queries from the same
 * codec, the squared distances of the tree over the decoded floats to the
 * last bit (every term and partial sum is then an integer multiple of
 * unit^2 below 2^24 unit^2, exact in float whatever the order).
 */
#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

namespace vslam
{
class BestBinFirstTree
{
   public:
	static constexpr int kLeafSize = 8;

	/** Scratch memory for searches, reused from query to query. */
	struct Scratch
	{
		struct Branch
		{
			float bound;  //!< squared distance from the query to the cell
			int32_t node;
			int32_t step;  //!< the cell's last offset in `steps` (-1: none)
			bool operator>(const Branch& o) const { return bound > o.bound; }
		};
		/** The cell's offset from the query along one dimension, set on
		 * turning away from the query; a cell's offsets are its chain of
		 * steps (later ones replace earlier ones along the same dimension),
		 * so a branch waiting in the queue costs one step, not a copy of
		 * all its offsets. */
		struct Step
		{
			int32_t previous;
			int32_t dim;
			float offset;
		};
		std::vector<Branch> queue;  //!< a min-heap on bound
		std::vector<Step> steps;
		std::vector<int32_t> chain;
		std::vector<float> offsets;  //!< the cell being descended, one per dimension
	};

	/** Over a copy of `rows` (at least one row): CV_32F values, or CV_8S
	 * codes for the values unit x code. search() offers rows by their
	 * number in `rows`; queries are values (floats). */
	explicit BestBinFirstTree(const cv::Mat& rows, float unit = 1.f);

	/** Offers rows to `nearest` (offer(int row, float squaredDistance);
	 * worstDist(): the squared distance beyond which no row is wanted),
	 * nearest cells first, until `maxCompared` rows were compared or no
	 * cell left can hold a wanted row. At least one leaf is compared. */
	template <class Nearest>
	void search(const float* query, int maxCompared, Nearest& nearest, Scratch& scratch) const;

	int rows() const { return m_rows.rows; }
	/** The rows as they were given (same type). */
	cv::Mat rowsInInputOrder() const;
	/** Memory held: the rows, nodes and row numbers. */
	size_t bytes() const
	{
		return m_rows.total() * m_rows.elemSize() + m_nodes.capacity() * sizeof(Node) + m_order.capacity() * sizeof(int32_t);
	}

   private:
	struct Node
	{
		int32_t dim;  //!< split dimension; -1 for a leaf
		float split;  //!< rows below go left (node + 1), rows above right
		int32_t right;  //!< inner node: the right child
		int32_t begin, end;  //!< leaf: its rows, m_order[begin..end)
	};
	int32_t build(int32_t begin, int32_t end);
	/** To the row stored at `at` (leaf order). */
	float squaredDistance(const float* query, int32_t at) const
	{
		if (m_rows.depth() == CV_8S) return squaredDistanceToCode(query, m_rows.ptr<int8_t>(at));
		using Vector = Eigen::Map<const Eigen::VectorXf>;
		return (Vector(query, m_dims) - Vector(m_rows.ptr<float>(at), m_dims)).squaredNorm();
	}
	float squaredDistanceToCode(const float* query, const int8_t* code) const
	{
		if (m_dims == kCommonDims)
		{
			// The default search codes' width as a constant: the codes are
			// converted, then Eigen's vectorized sum (any order is exact).
			Eigen::Matrix<float, kCommonDims, 1> v;
			for (int d = 0; d < kCommonDims; d++) v[d] = m_unit * static_cast<float>(code[d]);
			return (Eigen::Map<const Eigen::Matrix<float, kCommonDims, 1>>(query) - v).squaredNorm();
		}
		float sum = 0;
		for (int d = 0; d < m_dims; d++)
		{
			const float diff = query[d] - m_unit * static_cast<float>(code[d]);
			sum += diff * diff;
		}
		return sum;
	}
	static constexpr int kCommonDims = 16;
	/** Value of element `dim` of row `row` of m_rows. */
	float value(int32_t row, int dim) const
	{
		return m_rows.depth() == CV_8S ? m_unit * static_cast<float>(m_rows.ptr<int8_t>(row)[dim])
									   : m_rows.ptr<float>(row)[dim];
	}

	cv::Mat m_rows;  //!< leaf order: stored row i is input row m_order[i]
	int m_dims;
	float m_unit;  //!< value of one unit of a CV_8S code
	std::vector<Node> m_nodes;  //!< preorder; the root first
	std::vector<int32_t> m_order;  //!< row numbers, grouped by leaf
};

template <class Nearest>
void BestBinFirstTree::search(const float* query, int maxCompared, Nearest& nearest, Scratch& scratch) const
{
	const auto later = std::greater<Scratch::Branch>();
	scratch.queue.clear();
	scratch.steps.clear();
	scratch.queue.push_back({0.f, 0, -1});
	scratch.offsets.resize(static_cast<size_t>(m_dims));
	float* offset = scratch.offsets.data();
	int compared = 0;
	while (!scratch.queue.empty())
	{
		std::pop_heap(scratch.queue.begin(), scratch.queue.end(), later);
		const Scratch::Branch branch = scratch.queue.back();
		scratch.queue.pop_back();
		// The queue's nearest cell is too far: so are all the others.
		if (branch.bound >= nearest.worstDist() || (compared > 0 && compared >= maxCompared)) break;
		// The cell's offsets: its steps, the earliest first.
		std::fill_n(offset, m_dims, 0.f);
		scratch.chain.clear();
		for (int32_t s = branch.step; s >= 0; s = scratch.steps[s].previous) scratch.chain.push_back(s);
		for (auto s = scratch.chain.rbegin(); s != scratch.chain.rend(); ++s)
			offset[scratch.steps[*s].dim] = scratch.steps[*s].offset;
		const float bound = branch.bound;  // the nearer child keeps its cell's offsets
		const int32_t step = branch.step;
		int32_t node = branch.node;
		while (m_nodes[node].dim >= 0)
		{
			const Node& n = m_nodes[node];
			const float diff = query[n.dim] - n.split;
			const int32_t nearer = diff < 0 ? node + 1 : n.right;
			const int32_t farther = diff < 0 ? n.right : node + 1;
			// The farther cell lies at least |diff| away along n.dim, which
			// replaces the offset an earlier split along it had set.
			const float farBound = bound - offset[n.dim] * offset[n.dim] + diff * diff;
			if (farBound < nearest.worstDist())
			{
				scratch.steps.push_back({step, n.dim, diff});
				scratch.queue.push_back({farBound, farther, static_cast<int32_t>(scratch.steps.size() - 1)});
				std::push_heap(scratch.queue.begin(), scratch.queue.end(), later);
			}
			node = nearer;
		}
		for (int32_t i = m_nodes[node].begin; i < m_nodes[node].end; i++)
			nearest.offer(m_order[i], squaredDistance(query, i));
		compared += m_nodes[node].end - m_nodes[node].begin;
	}
}
}  // namespace vslam

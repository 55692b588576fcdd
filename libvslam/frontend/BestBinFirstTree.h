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
 * are read from one block of memory.
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

	/** Over a copy of `rows` (CV_32F, at least one row); search() offers
	 * rows by their number in `rows`. */
	explicit BestBinFirstTree(const cv::Mat& rows);

	/** Offers rows to `nearest` (offer(int row, float squaredDistance);
	 * worstDist(): the squared distance beyond which no row is wanted),
	 * nearest cells first, until `maxCompared` rows were compared or no
	 * cell left can hold a wanted row. At least one leaf is compared. */
	template <class Nearest>
	void search(const float* query, int maxCompared, Nearest& nearest, Scratch& scratch) const;

	int rows() const { return m_rows.rows; }
	/** The rows as they were given. */
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
		using Vector = Eigen::Map<const Eigen::VectorXf>;
		return (Vector(query, m_dims) - Vector(m_rows.ptr<float>(at), m_dims)).squaredNorm();
	}

	cv::Mat m_rows;  //!< leaf order: stored row i is input row m_order[i]
	int m_dims;
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

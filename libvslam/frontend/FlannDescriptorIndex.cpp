#include <libvslam/frontend/FlannDescriptorIndex.h>
#include <libvslam/frontend/IndexLevels.h>

#include <algorithm>

using namespace vslam;

namespace
{
constexpr uint64_t kFlannSeed = 0x5eed;
/** Nearest rows asked of each level: two, and two more when removed rows
 * may take their places. */
constexpr int kNeighbours = 2;
constexpr int kSpareForRemoved = 2;
/** The logarithmic method's merge ratio (IndexLevels.h). Each level costs
 * a search its own per-query overhead, which dominates with few checks, so
 * fewer, larger levels search faster, for rebuilds of O(kMergeRatio) times
 * each row. */
constexpr int kMergeRatio = 4;
}  // namespace

FlannDescriptorIndex::FlannDescriptorIndex(const DescriptorCodec& codec, int trees, int checks)
	: DescriptorIndex(codec), m_trees(trees), m_checks(checks)
{
}

FlannDescriptorIndex::~FlannDescriptorIndex() = default;

void FlannDescriptorIndex::build(Level& level) const
{
	const cv::RNG callers = cv::theRNG();
	cv::theRNG() = cv::RNG(kFlannSeed);
	level.index = std::make_unique<cv::flann::Index>(
		DescriptorCodec::decode(level.codes), cv::flann::KDTreeIndexParams(m_trees), cvflann::FLANN_DIST_L2);
	cv::theRNG() = callers;
}

void FlannDescriptorIndex::doAdd(size_t firstRow, const cv::Mat& indexRows)
{
	Level added;
	added.codes = indexRows;
	added.firstRow = firstRow;
	appendAndMerge(m_levels, std::move(added), kMergeRatio);
	build(m_levels.back());
}

void FlannDescriptorIndex::doSearch(const cv::Mat& queries, std::vector<TwoNearestLiveRows>& out) const
{
	const cv::flann::SearchParams params(m_checks);
	for (const Level& level : m_levels)
	{
		// Queries whose nearest rows in this level may all be removed ask
		// again for more, until two live ones or the whole level (rows
		// offered twice count once).
		std::vector<int> pending(static_cast<size_t>(queries.rows));
		for (int q = 0; q < queries.rows; q++) pending[q] = q;
		int k = std::min(level.codes.rows, kNeighbours + (anyRemoved() ? kSpareForRemoved : 0));
		while (!pending.empty())
		{
			cv::Mat asked = queries, indices, dists;
			if (pending.size() < static_cast<size_t>(queries.rows))  // a retry: only those queries
			{
				asked.create(static_cast<int>(pending.size()), queries.cols, CV_32F);
				for (size_t i = 0; i < pending.size(); i++) queries.row(pending[i]).copyTo(asked.row(static_cast<int>(i)));
			}
			level.index->knnSearch(asked, indices, dists, k, params);
			std::vector<int> again;
			for (size_t i = 0; i < pending.size(); i++)
			{
				int live = 0;
				for (int j = 0; j < k; j++)
				{
					const int local = indices.at<int>(static_cast<int>(i), j);
					if (local < 0) continue;
					const size_t row = level.firstRow + static_cast<size_t>(local);
					live += !removed()[row];
					out[pending[i]].offer(row, dists.at<float>(static_cast<int>(i), j));
				}
				if (live < kNeighbours && k < level.codes.rows) again.push_back(pending[i]);
			}
			pending.swap(again);
			k = std::min(level.codes.rows, 4 * k);
		}
	}
}

size_t FlannDescriptorIndex::doBytes() const
{
	// FLANN does not report its memory: its float copy of the rows
	// (miniflann.hpp's features_clone) and its k-d tree (kdtree_index.h):
	// one row index and, per tree, 2n - 1 nodes of two child pointers, a
	// point pointer, a split dimension and value.
	constexpr size_t kNodeBytes = 3 * sizeof(void*) + sizeof(int) + sizeof(float);
	size_t b = 0;
	for (const Level& level : m_levels)
	{
		const auto n = static_cast<size_t>(level.codes.rows);
		const size_t flannRows = level.codes.total() * sizeof(float);
		b += level.codes.total() * level.codes.elemSize() + flannRows + n * sizeof(int) +
			static_cast<size_t>(m_trees) * (2 * n - 1) * kNodeBytes;
	}
	return b;
}

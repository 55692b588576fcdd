#include <libvslam/frontend/BestBinFirstDescriptorIndex.h>
#include <libvslam/frontend/IndexLevels.h>

using namespace vslam;

namespace
{
/** The logarithmic method's merge ratio (IndexLevels.h), as for FLANN. */
constexpr int kMergeRatio = 4;
}  // namespace

BestBinFirstDescriptorIndex::BestBinFirstDescriptorIndex(const DescriptorCodec& codec, int maxCompared)
	: DescriptorIndex(codec), m_maxCompared(maxCompared)
{
}

BestBinFirstDescriptorIndex::~BestBinFirstDescriptorIndex() = default;

void BestBinFirstDescriptorIndex::doAdd(size_t firstRow, const cv::Mat& indexRows)
{
	Level added;
	added.codes = indexRows;  // the tree reads bytes as kProjectedStep x byte
	added.firstRow = firstRow;
	appendAndMerge(m_levels, std::move(added), kMergeRatio);
	Level& last = m_levels.back();
	last.index = std::make_unique<BestBinFirstTree>(last.codes, DescriptorCodec::kProjectedStep);
	last.codes.release();  // the tree holds a copy, leaf by leaf
}

cv::Mat BestBinFirstDescriptorIndex::Level::takeCodes()
{
	cv::Mat out = index ? index->rowsInInputOrder() : codes;
	index.reset();
	codes.release();
	return out;
}

void BestBinFirstDescriptorIndex::doSearch(const cv::Mat& queries, std::vector<TwoNearestLiveRows>& out) const
{
	/** A level's rows offered as the index's rows (removed ones are
	 * ignored by TwoNearestLiveRows, so they never bound the search). */
	struct LevelRows
	{
		TwoNearestLiveRows* nearest;
		size_t firstRow;
		float worstDist() const { return nearest->worstDist(); }
		void offer(int32_t row, float dist) const { nearest->offer(firstRow + static_cast<size_t>(row), dist); }
	};
	BestBinFirstTree::Scratch scratch;
	for (int q = 0; q < queries.rows; q++)
		for (const Level& level : m_levels)
		{
			LevelRows rows{&out[static_cast<size_t>(q)], level.firstRow};
			level.index->search(queries.ptr<float>(q), m_maxCompared, rows, scratch);
		}
}

size_t BestBinFirstDescriptorIndex::doBytes() const
{
	size_t b = 0;
	for (const Level& level : m_levels) b += level.index->bytes();
	return b;
}

#pragma once
/** \file BestBinFirstDescriptorIndex.h
 * DescriptorIndex on best-bin-first k-d trees with leaf buckets
 * (BestBinFirstTree.h), one per level of the logarithmic method
 * (IndexLevels.h), each searched with a budget of codes compared per query.
 * Exact when the budget covers the level; deterministic (no random
 * choices). Against FLANN's k-d tree, which descends once per row
 * compared, a descent here compares a leaf's rows, so the same recall
 * costs fewer descents.
 */
#include <libvslam/frontend/BestBinFirstTree.h>
#include <libvslam/frontend/DescriptorCodec.h>
#include <libvslam/frontend/DescriptorIndex.h>

#include <memory>

namespace vslam
{
class BestBinFirstDescriptorIndex : public DescriptorIndex
{
   public:
	BestBinFirstDescriptorIndex(const DescriptorCodec& codec, int maxCompared);
	~BestBinFirstDescriptorIndex() override;
	size_t levels() const { return m_levels.size(); }

   protected:
	void doAdd(size_t firstRow, const cv::Mat& indexRows) override;
	void doSearch(const cv::Mat& queries, std::vector<TwoNearestLiveRows>& out) const override;
	size_t doBytes() const override;

   private:
	struct Level
	{
		/** One row per descriptor, until the tree holds them: the codec's
		 * CV_8S codes if it projects, else CV_32F values. */
		cv::Mat codes;
		size_t firstRow = 0;  //!< levels hold consecutive rows
		std::unique_ptr<BestBinFirstTree> index;
		int rows() const { return index ? index->rows() : codes.rows; }
		cv::Mat takeCodes();
	};

	int m_maxCompared;
	std::vector<Level> m_levels;  //!< oldest (largest) first
};
}  // namespace vslam

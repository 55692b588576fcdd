#pragma once
/** \file FlannDescriptorIndex.h
 * DescriptorIndex on OpenCV FLANN randomized k-d trees (Muja and Lowe),
 * searched with a bounded number of leaf checks per query, so a query's
 * cost grows with the logarithm of the map, not with the map.
 *
 * FLANN's trees are static, so insertion follows the logarithmic method
 * (IndexLevels.h): a search visits O(log n) levels, each with the same
 * check budget.
 *
 * FLANN draws its random split choices from cv::theRNG(): every build runs
 * on a fixed seed and restores the caller's generator, so results are the
 * same on every run and nothing else's random stream changes.
 *
 * cv::flann::Index searches a copy of the rows it was built on (OpenCV
 * 4.x keeps a clone, against dangling pointers), so the level keeps its
 * own rows only to merge levels, as the codec's codes: signed bytes when
 * it projects (a quarter of the floats), and bytes() counts both.
 */
#include <libvslam/frontend/DescriptorCodec.h>
#include <libvslam/frontend/DescriptorIndex.h>
#include <opencv2/flann.hpp>

namespace vslam
{
class FlannDescriptorIndex : public DescriptorIndex
{
   public:
	FlannDescriptorIndex(const DescriptorCodec& codec, int trees, int checks);
	~FlannDescriptorIndex() override;
	size_t levels() const { return m_levels.size(); }

   protected:
	void doAdd(size_t firstRow, const cv::Mat& indexRows) override;
	void doSearch(const cv::Mat& queries, std::vector<TwoNearestLiveRows>& out) const override;
	size_t doBytes() const override;

   private:
	struct Level
	{
		/** One row per descriptor, to merge levels: the codec's CV_8S
		 * codes if it projects, else CV_32F values (FLANN searches its own
		 * float copy). */
		cv::Mat codes;
		size_t firstRow = 0;  //!< levels hold consecutive rows
		std::unique_ptr<cv::flann::Index> index;
		int rows() const { return codes.rows; }
		cv::Mat takeCodes()
		{
			index.reset();
			return codes;
		}
	};
	void build(Level& level) const;

	int m_trees;
	int m_checks;
	std::vector<Level> m_levels;  //!< oldest (largest) first
};
}  // namespace vslam

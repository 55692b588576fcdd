#pragma once
/** \file IndexLevels.h
 * The logarithmic method (Bentley and Saxe) for descriptor indices whose
 * search structures are static: the rows live in levels, each a structure
 * over a contiguous block of codes, oldest (largest) first. A new block is
 * a new level, and while a level holds at most `mergeRatio` times the rows
 * of the one after it the two merge; the caller then rebuilds the last
 * level. Each level then holds more than mergeRatio times the next, so a
 * map of L blocks has at most about log_mergeRatio(L) levels, and each row
 * is rebuilt O(mergeRatio log L) times over the map's life.
 *
 * Level: `int rows() const`; `cv::Mat takeCodes()`, its codes (one row per
 * descriptor, in row order), dropping its search structure; and
 * `cv::Mat codes`, the block the caller builds the merged level from.
 */
#include <opencv2/core.hpp>

#include <vector>

namespace vslam
{
template <class Level>
void appendAndMerge(std::vector<Level>& levels, Level added, int mergeRatio)
{
	levels.push_back(std::move(added));
	while (levels.size() >= 2 && levels[levels.size() - 2].rows() <= mergeRatio * levels.back().rows())
	{
		const cv::Mat last = levels.back().takeCodes();
		levels.pop_back();
		cv::Mat merged;
		cv::vconcat(levels.back().takeCodes(), last, merged);
		levels.back().codes = merged;
	}
}
}  // namespace vslam

#pragma once
/** \file Median.h  The median of a sample (upper median for even sizes; 0 if empty). */
#include <algorithm>
#include <vector>

namespace vslam
{
inline double median(std::vector<double> v)
{
	if (v.empty()) return 0;
	std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
	return v[v.size() / 2];
}
}  // namespace vslam

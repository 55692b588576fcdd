#pragma once
/** \file ErrorSummary.h  RMSE, mean, median and max of a list of errors,
 * the statistics the TUM benchmark tools (and evo) report. */
#include <cstddef>
#include <vector>

namespace vslam
{
struct ErrorSummary
{
	size_t count = 0;
	double rmse = 0, mean = 0, median = 0, max = 0;
};

/** The statistics of \a errors (all zero if empty); the median of an even
 * count is the mean of the two middle values. */
ErrorSummary summarizeErrors(const std::vector<double>& errors);
}  // namespace vslam

#include <libvslam/eval/ErrorSummary.h>

#include <algorithm>
#include <cmath>

namespace vslam
{
ErrorSummary summarizeErrors(const std::vector<double>& errors)
{
	ErrorSummary s;
	s.count = errors.size();
	if (errors.empty()) return s;
	double sum = 0, sum2 = 0;
	for (const double e : errors)
	{
		sum += e;
		sum2 += e * e;
		s.max = std::max(s.max, e);
	}
	s.mean = sum / double(s.count);
	s.rmse = std::sqrt(sum2 / double(s.count));
	std::vector<double> sorted = errors;
	std::sort(sorted.begin(), sorted.end());
	const size_t n = sorted.size();
	s.median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
	return s;
}
}  // namespace vslam

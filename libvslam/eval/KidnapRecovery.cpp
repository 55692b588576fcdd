#include <libvslam/eval/KidnapRecovery.h>

#include <algorithm>
#include <cstddef>

namespace vslam
{
std::optional<double> recoveryTime(const std::vector<double>& times, const std::vector<double>& errors,
	double kidnapTime, const RecoveryCriterion& c)
{
	const size_t n = std::min(times.size(), errors.size());
	// Scan forward, tracking where the current run of errors within the
	// bound started; once a sample lies a hold time after that start, every
	// sample of [start, start + hold) was within.
	std::optional<size_t> runStart;
	for (size_t i = 0; i < n; i++)
	{
		if (times[i] < kidnapTime) continue;
		if (runStart && times[i] - times[*runStart] >= c.hold - 1e-9) return times[*runStart] - kidnapTime;
		if (errors[i] > c.within)
			runStart.reset();
		else if (!runStart)
			runStart = i;
	}
	return std::nullopt;
}
}  // namespace vslam

#include <libvslam/eval/Median.h>
#include <libvslam/eval/MeasurementAccuracy.h>

#include <algorithm>
#include <cmath>

namespace vslam
{
namespace
{
struct ErrorList
{
	std::vector<double> position, heading;
	size_t beyond = 0;

	MeasurementErrorStats stats() const
	{
		MeasurementErrorStats s;
		s.count = position.size();
		s.medianPosition = median(position);
		s.medianHeadingDeg = median(heading) * 180 / M_PI;
		double sp = 0, sh = 0;
		for (size_t i = 0; i < position.size(); i++) sp += position[i] * position[i], sh += heading[i] * heading[i];
		s.rmsPosition = s.count ? std::sqrt(sp / s.count) : 0;
		s.rmsHeadingDeg = s.count ? std::sqrt(sh / s.count) * 180 / M_PI : 0;
		s.beyond3Sigma = beyond;
		return s;
	}
};
}  // namespace

MeasurementAccuracy evaluateMeasurements(const std::vector<LandmarkMeasurementRecord>& measurements,
	const std::map<int64_t, double>& creationTimes, const Trajectory& truth,
	const CMeasurementExtractor::TVisualOptions& sigma, const CPreFilter::TOptions& prefilter)
{
	constexpr double kMaxGap = 1.0;  // s between ground-truth samples
	const CPreFilter filter(prefilter);
	MeasurementAccuracy out;
	ErrorList all, accepted;
	for (const auto& m : measurements)
	{
		out.measurements++;
		const auto created = creationTimes.find(m.landmarkID);
		const auto now = interpolate(truth, m.t, kMaxGap);
		if (created == creationTimes.end() || !now)
		{
			out.withoutTruth++;
			continue;
		}
		const auto frame = interpolate(truth, created->second, kMaxGap);
		if (!frame)
		{
			out.withoutTruth++;
			continue;
		}
		const se2::Pose expected = se2::between(*now, *frame);
		const Eigen::Vector3d e = se2::difference(m.z, expected);
		const bool beyond = std::abs(e[0]) > 3 * sigma.std_dx || std::abs(e[1]) > 3 * sigma.std_dy ||
			std::abs(e[2]) > 3 * sigma.std_dphi;
		const bool ok = filter.check(m.ProjErrRMS, m.NPoints, m.Slope) == CPreFilter::Verdict::Accepted;
		out.errors.push_back({m, expected, e, ok, beyond});
		for (ErrorList* list : {&all, &accepted})
		{
			if (list == &accepted && !ok) continue;
			list->position.push_back(std::hypot(e[0], e[1]));
			list->heading.push_back(std::abs(e[2]));
			list->beyond += beyond;
		}
	}
	out.all = all.stats();
	out.accepted = accepted.stats();
	return out;
}
}  // namespace vslam

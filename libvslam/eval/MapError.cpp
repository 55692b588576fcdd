#include <libvslam/eval/MapError.h>

#include <cmath>
#include <unordered_map>

namespace vslam
{
MapErrorStats computeMapError(const LandmarkMap& estimate, const LandmarkMap& truth, const se2::Pose& transform)
{
	MapErrorStats s;
	s.estimated = estimate.size();
	s.truth = truth.size();
	std::unordered_map<LandmarkKey, const LandmarkEstimate*, LandmarkKeyHash> byKey;
	for (const auto& [key, l] : truth) byKey[key] = &l;
	std::vector<double> positionErrors;
	double heading2 = 0;
	for (const auto& [key, l] : estimate)
	{
		const auto it = byKey.find(key);
		if (it == byKey.end()) continue;
		const se2::Pose e = se2::compose(transform, {l.mean[0], l.mean[1], l.mean[2]});
		const auto& t = it->second->mean;
		positionErrors.push_back(std::hypot(e.x - t[0], e.y - t[1]));
		if (key.kind == LandmarkKind::Pose)
		{
			const double d = se2::wrap(e.phi - t[2]);
			heading2 += d * d;
			s.poses++;
		}
	}
	s.matched = positionErrors.size();
	s.position = summarizeErrors(positionErrors);
	s.headingRmse = s.poses ? std::sqrt(heading2 / double(s.poses)) : 0.0;
	return s;
}
}  // namespace vslam

#include <libvslam/eval/TrajectoryAssociation.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace vslam
{
bool hasOnlySteps(const Trajectory& groundTruth)
{
	return !groundTruth.empty() &&
		std::all_of(groundTruth.begin(), groundTruth.end(),
			[](const TimedPose& p) { return std::isnan(p.t) && p.step >= 0; });
}

std::vector<AssociatedPose> associate(const Trajectory& estimate, const Trajectory& groundTruth, double maxGap)
{
	std::vector<AssociatedPose> pairs;
	if (hasOnlySteps(groundTruth))
	{
		std::map<long, se2::Pose> byStep;
		for (const auto& g : groundTruth) byStep[g.step] = g.pose;
		for (const auto& e : estimate)
			if (const auto g = byStep.find(e.step); e.step >= 0 && g != byStep.end())
				pairs.push_back({e.t, e.pose, g->second});
		return pairs;
	}
	for (const auto& e : estimate)
		if (const auto g = interpolate(groundTruth, e.t, maxGap)) pairs.push_back({e.t, e.pose, *g});
	return pairs;
}
}  // namespace vslam

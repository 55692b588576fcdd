#include <libvslam/app/KeyframesAlongOdometry.h>

#include <limits>
#include <optional>

using namespace vslam;

namespace
{
/** Keyframe kf carried by the odometry from its time to the odometry pose at. */
std::optional<se2::Pose> carried(const TimedPose& kf, const Trajectory& odometry, const TimedPose& at)
{
	const auto odometryAtKeyframe = interpolate(odometry, kf.t, std::numeric_limits<double>::infinity());
	if (!odometryAtKeyframe) return std::nullopt;
	return se2::compose(kf.pose, se2::between(*odometryAtKeyframe, at.pose));
}

se2::Pose blend(const se2::Pose& a, const se2::Pose& b, double w)
{
	return {a.x + w * (b.x - a.x), a.y + w * (b.y - a.y), se2::wrap(a.phi + w * se2::wrap(b.phi - a.phi))};
}
}  // namespace

Trajectory vslam::keyframesAlongOdometry(const Trajectory& keyframes, const Trajectory& odometry)
{
	Trajectory out;
	if (keyframes.empty()) return out;
	// Times that do not order the keyframes (a rawlog whose clock stands
	// still, as MRPT's simulated ones) cannot place the steps between them.
	for (size_t k = 1; k < keyframes.size(); k++)
		if (!(keyframes[k].t > keyframes[k - 1].t)) return keyframes;
	out.reserve(odometry.size());
	size_t next = 0;  // the first keyframe after the step
	for (const TimedPose& step : odometry)
	{
		while (next < keyframes.size() && keyframes[next].t <= step.t) next++;
		const auto fromPrevious = next > 0 ? carried(keyframes[next - 1], odometry, step) : std::nullopt;
		const auto fromNext = next < keyframes.size() ? carried(keyframes[next], odometry, step) : std::nullopt;
		TimedPose p = step;
		if (fromPrevious && fromNext)
		{
			const double t0 = keyframes[next - 1].t, t1 = keyframes[next].t;
			p.pose = blend(*fromPrevious, *fromNext, (step.t - t0) / (t1 - t0));
		}
		else if (fromPrevious || fromNext)
			p.pose = fromPrevious ? *fromPrevious : *fromNext;
		else
			continue;  // no odometry at either keyframe's time
		out.push_back(p);
	}
	return out;
}

#include <libvslam/eval/GroundTruthCheck.h>

#include <cmath>

namespace vslam
{
namespace
{
constexpr double kMaxInterpolationGap = 1.0;  // s: truth is not invented across gaps
}

double groundTruthCover(const Trajectory& path, const Trajectory& truth)
{
	if (path.empty()) return 0;
	size_t covered = 0;
	for (const auto& p : path)
		if (interpolate(truth, p.t, kMaxInterpolationGap)) covered++;
	return double(covered) / double(path.size());
}

double odometryDisagreement(const Trajectory& odometry, const Trajectory& truth)
{
	size_t moving = 0, disagreeing = 0;
	size_t i = 0;
	while (i < odometry.size())
	{
		size_t j = i + 1;
		while (j < odometry.size() && odometry[j].t < odometry[i].t + 1.0) j++;
		if (j >= odometry.size()) break;
		const auto a = interpolate(truth, odometry[i].t, kMaxInterpolationGap);
		const auto b = interpolate(truth, odometry[j].t, kMaxInterpolationGap);
		if (a && b)
		{
			// Motion in the robot's own frame: the same for the odometry and
			// the truth whatever their world frames.
			const se2::Pose odo = se2::between(odometry[i].pose, odometry[j].pose);
			const se2::Pose real = se2::between(*a, *b);
			const double odoDistance = std::hypot(odo.x, odo.y), realDistance = std::hypot(real.x, real.y);
			const double largest = std::max(odoDistance, realDistance);
			const double largestTurn = std::max(std::abs(odo.phi), std::abs(real.phi));
			const double turnTolerance = 10 * M_PI / 180;
			if (largest > 0.1 || largestTurn > turnTolerance)
			{
				moving++;
				if (std::hypot(odo.x - real.x, odo.y - real.y) > 0.1 + 0.5 * largest ||
					std::abs(se2::wrap(odo.phi - real.phi)) > turnTolerance + 0.5 * largestTurn)
					disagreeing++;
			}
		}
		i = j;
	}
	return moving < 5 ? NAN : double(disagreeing) / double(moving);
}
}  // namespace vslam

#include <libvslam/eval/GroundTruthCheck.h>
#include <libvslam/eval/TrajectoryAssociation.h>

#include <cmath>

namespace vslam
{
namespace
{
// The error figures' (TAteOptions): truth is not invented across longer gaps.
constexpr double kMaxInterpolationGap = 0.5;  // s
}

double groundTruthCover(const Trajectory& path, const Trajectory& truth)
{
	if (path.empty()) return 0;
	return double(associate(path, truth, kMaxInterpolationGap).size()) / double(path.size());
}

double odometryDisagreement(const Trajectory& odometry, const Trajectory& truth)
{
	// The same association as the error figures (by time, or by step for a
	// truth without times).
	const std::vector<AssociatedPose> pairs = associate(odometry, truth, kMaxInterpolationGap);
	size_t moving = 0, disagreeing = 0;
	for (size_t i = 0, j = 1; j < pairs.size(); i = j, j = i + 1)
	{
		while (j < pairs.size() && pairs[j].t < pairs[i].t + 1.0) j++;  // false for NaN times: one pair
		if (j >= pairs.size()) break;
		// Motion in the robot's own frame: the same for the odometry and
		// the truth whatever their world frames.
		const se2::Pose odo = se2::between(pairs[i].estimate, pairs[j].estimate);
		const se2::Pose real = se2::between(pairs[i].truth, pairs[j].truth);
		const double largest = std::max(std::hypot(odo.x, odo.y), std::hypot(real.x, real.y));
		const double largestTurn = std::max(std::abs(odo.phi), std::abs(real.phi));
		const double turnTolerance = 10 * M_PI / 180;
		if (largest <= 0.1 && largestTurn <= turnTolerance) continue;
		moving++;
		if (std::hypot(odo.x - real.x, odo.y - real.y) > 0.1 + 0.5 * largest ||
			std::abs(se2::wrap(odo.phi - real.phi)) > turnTolerance + 0.5 * largestTurn)
			disagreeing++;
	}
	return moving < 5 ? NAN : double(disagreeing) / double(moving);
}
}  // namespace vslam

#include <libvslam/eval/AbsoluteTrajectoryError.h>

#include <Eigen/Core>
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

AteStats computeAte(
	const Trajectory& estimate, const Trajectory& groundTruth, const AteOptions& o)
{
	std::vector<se2::Pose> est, gt;
	if (hasOnlySteps(groundTruth))
	{
		std::map<long, se2::Pose> byStep;
		for (const auto& g : groundTruth) byStep[g.step] = g.pose;
		for (const auto& e : estimate)
			if (const auto g = byStep.find(e.step); e.step >= 0 && g != byStep.end())
			{
				est.push_back(e.pose);
				gt.push_back(g->second);
			}
	}
	else
		for (const auto& e : estimate)
			if (const auto g = interpolate(groundTruth, e.t, o.maxGap))
			{
				est.push_back(e.pose);
				gt.push_back(*g);
			}
	AteStats s;
	s.associated = est.size();
	if (est.empty()) return s;

	// Least-squares rotation + translation (Umeyama without scale) in 2-D.
	double theta = 0;
	Eigen::Vector2d t(0, 0);
	if (o.align)
	{
		Eigen::Vector2d me(0, 0), mg(0, 0);
		for (size_t i = 0; i < est.size(); i++)
			me += Eigen::Vector2d(est[i].x, est[i].y), mg += Eigen::Vector2d(gt[i].x, gt[i].y);
		me /= est.size();
		mg /= est.size();
		double sdot = 0, scross = 0;
		for (size_t i = 0; i < est.size(); i++)
		{
			const Eigen::Vector2d a = Eigen::Vector2d(est[i].x, est[i].y) - me;
			const Eigen::Vector2d b = Eigen::Vector2d(gt[i].x, gt[i].y) - mg;
			sdot += a.dot(b);
			scross += a.x() * b.y() - a.y() * b.x();
		}
		theta = std::atan2(scross, sdot);
		t = mg - Eigen::Vector2d(std::cos(theta) * me.x() - std::sin(theta) * me.y(),
								 std::sin(theta) * me.x() + std::cos(theta) * me.y());
	}
	s.alignment = {t.x(), t.y(), theta};
	const double c = std::cos(theta), sn = std::sin(theta);
	double sum2 = 0, sum = 0, head2 = 0;
	for (size_t i = 0; i < est.size(); i++)
	{
		const double x = c * est[i].x - sn * est[i].y + t.x();
		const double y = sn * est[i].x + c * est[i].y + t.y();
		const double e = std::hypot(x - gt[i].x, y - gt[i].y);
		s.errors.push_back(e);
		sum += e;
		sum2 += e * e;
		s.max = std::max(s.max, e);
		const double dh = se2::wrap(est[i].phi + theta - gt[i].phi);
		head2 += dh * dh;
	}
	s.rmse = std::sqrt(sum2 / est.size());
	s.mean = sum / est.size();
	s.headingRmse = std::sqrt(head2 / est.size());
	std::vector<double> sorted = s.errors;
	std::sort(sorted.begin(), sorted.end());
	const size_t n = sorted.size();
	s.median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
	return s;
}
}  // namespace vslam

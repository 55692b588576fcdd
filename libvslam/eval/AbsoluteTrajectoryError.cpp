#include <libvslam/eval/AbsoluteTrajectoryError.h>
#include <libvslam/eval/ErrorSummary.h>
#include <libvslam/eval/TrajectoryAssociation.h>

#include <Eigen/Core>
#include <cmath>

namespace vslam
{
namespace
{
/** Least-squares rotation + translation (Umeyama without scale) in 2-D
 * that maps the estimates onto the truth. */
se2::Pose bestAlignment(const std::vector<AssociatedPose>& pairs)
{
	Eigen::Vector2d me(0, 0), mg(0, 0);
	for (const auto& p : pairs)
		me += Eigen::Vector2d(p.estimate.x, p.estimate.y), mg += Eigen::Vector2d(p.truth.x, p.truth.y);
	me /= double(pairs.size());
	mg /= double(pairs.size());
	double sdot = 0, scross = 0;
	for (const auto& p : pairs)
	{
		const Eigen::Vector2d a = Eigen::Vector2d(p.estimate.x, p.estimate.y) - me;
		const Eigen::Vector2d b = Eigen::Vector2d(p.truth.x, p.truth.y) - mg;
		sdot += a.dot(b);
		scross += a.x() * b.y() - a.y() * b.x();
	}
	const double theta = std::atan2(scross, sdot);
	const Eigen::Vector2d t = mg - Eigen::Vector2d(std::cos(theta) * me.x() - std::sin(theta) * me.y(),
									   std::sin(theta) * me.x() + std::cos(theta) * me.y());
	return {t.x(), t.y(), theta};
}
}  // namespace

AteStats computeAte(const Trajectory& estimate, const Trajectory& groundTruth, const AteOptions& o)
{
	const std::vector<AssociatedPose> pairs = associate(estimate, groundTruth, o.maxGap);
	AteStats s;
	s.associated = pairs.size();
	if (pairs.empty()) return s;
	if (o.align) s.alignment = bestAlignment(pairs);
	double head2 = 0;
	for (const auto& p : pairs)
	{
		const se2::Pose e = se2::compose(s.alignment, p.estimate);
		s.times.push_back(p.t);
		s.errors.push_back(std::hypot(e.x - p.truth.x, e.y - p.truth.y));
		s.headingErrors.push_back(se2::wrap(e.phi - p.truth.phi));
		head2 += s.headingErrors.back() * s.headingErrors.back();
	}
	const ErrorSummary summary = summarizeErrors(s.errors);
	s.rmse = summary.rmse;
	s.mean = summary.mean;
	s.median = summary.median;
	s.max = summary.max;
	s.headingRmse = std::sqrt(head2 / double(pairs.size()));
	return s;
}
}  // namespace vslam

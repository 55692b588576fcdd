#include <libvslam/eval/AbsoluteTrajectoryError.h>
#include <libvslam/eval/ErrorSummary.h>
#include <libvslam/eval/TrajectoryAssociation.h>

#include <Eigen/Core>
#include <cmath>

namespace vslam
{
namespace
{
/** Least-squares rotation + translation in 2-D, and with `withScale` a
 * scale (Umeyama 1991), that map the estimates onto the truth: truth ~
 * R(theta) scale x + t. */
se2::Pose bestAlignment(const std::vector<AssociatedPose>& pairs, bool withScale, double& scale)
{
	Eigen::Vector2d me(0, 0), mg(0, 0);
	for (const auto& p : pairs)
		me += Eigen::Vector2d(p.estimate.x, p.estimate.y), mg += Eigen::Vector2d(p.truth.x, p.truth.y);
	me /= double(pairs.size());
	mg /= double(pairs.size());
	double sdot = 0, scross = 0, spread = 0;
	for (const auto& p : pairs)
	{
		const Eigen::Vector2d a = Eigen::Vector2d(p.estimate.x, p.estimate.y) - me;
		const Eigen::Vector2d b = Eigen::Vector2d(p.truth.x, p.truth.y) - mg;
		sdot += a.dot(b);
		scross += a.x() * b.y() - a.y() * b.x();
		spread += a.squaredNorm();
	}
	const double theta = std::atan2(scross, sdot);
	// The scale that minimizes the squared errors at that rotation; none
	// for an estimate that does not move (a single point has no scale).
	scale = withScale && spread > 0 ? std::hypot(sdot, scross) / spread : 1;
	const Eigen::Vector2d t = mg - scale * Eigen::Vector2d(std::cos(theta) * me.x() - std::sin(theta) * me.y(),
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
	if (o.align) s.alignment = bestAlignment(pairs, o.alignScale, s.alignmentScale);
	double head2 = 0;
	for (const auto& p : pairs)
	{
		const se2::Pose scaled{s.alignmentScale * p.estimate.x, s.alignmentScale * p.estimate.y, p.estimate.phi};
		const se2::Pose e = se2::compose(s.alignment, scaled);
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

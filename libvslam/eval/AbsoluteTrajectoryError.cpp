#include <libvslam/eval/AbsoluteTrajectoryError.h>
#include <libvslam/eval/ErrorSummary.h>
#include <libvslam/eval/TrajectoryAssociation.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace vslam
{
namespace
{
/** Least-squares rotation + translation in 2-D, and with `withScale` a
 * scale, that map the estimates onto the truth: truth ~ R(theta) scale x + t
 * (Umeyama 1991, Eigen's implementation). */
se2::Pose bestAlignment(const std::vector<AssociatedPose>& pairs, bool withScale, double& scale)
{
	const auto n = static_cast<Eigen::Index>(pairs.size());
	Eigen::Matrix2Xd estimate(2, n), truth(2, n);
	for (Eigen::Index i = 0; i < n; i++)
	{
		const AssociatedPose& p = pairs[static_cast<size_t>(i)];
		estimate.col(i) << p.estimate.x, p.estimate.y;
		truth.col(i) << p.truth.x, p.truth.y;
	}
	// An estimate that does not move has no rotation or scale to find (a
	// single point): only the offset of the means.
	const Eigen::Vector2d mean = estimate.rowwise().mean();
	if ((estimate.colwise() - mean).squaredNorm() == 0)
	{
		scale = 1;
		const Eigen::Vector2d t = truth.rowwise().mean() - mean;
		return {t.x(), t.y(), 0};
	}
	const Eigen::Matrix3d T = Eigen::umeyama(estimate, truth, withScale);
	scale = T.block<2, 1>(0, 0).norm();
	return {T(0, 2), T(1, 2), std::atan2(T(1, 0), T(0, 0))};
}
}  // namespace

AteStats computeAte(const Trajectory& estimate, const Trajectory& groundTruth, const TAteOptions& o)
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

#include <libvslam/eval/HeadingChangeAccuracy.h>
#include <libvslam/eval/Median.h>

#include <cmath>

using namespace vslam;

HeadingChangeAccuracy vslam::evaluateHeadingChanges(
	const std::vector<HeadingChangeRecord>& records, const Trajectory& truth)
{
	constexpr double kMaxGap = 1.0;  // s between ground-truth samples
	constexpr double kDeg = 180 / M_PI;
	HeadingChangeAccuracy a;
	std::vector<double> absError, absOdometry, absNormalized, stds;
	double sumSquared = 0, sumSquaredOdometry = 0, sumSquaredNormalized = 0;
	for (const auto& r : records)
	{
		const auto p0 = interpolate(truth, r.t0, kMaxGap), p1 = interpolate(truth, r.t1, kMaxGap);
		if (!p0 || !p1)
		{
			a.withoutTruth++;
			continue;
		}
		const double trueDphi = se2::wrap(p1->phi - p0->phi);
		const double e = se2::wrap(r.dphi - trueDphi), eo = se2::wrap(r.odometryDphi - trueDphi);
		a.count++;
		a.errors.push_back({r, trueDphi});
		absError.push_back(std::abs(e) * kDeg);
		absOdometry.push_back(std::abs(eo) * kDeg);
		stds.push_back(r.stdDphi * kDeg);
		sumSquared += e * e;
		sumSquaredOdometry += eo * eo;
		a.sumErrorDeg += e * kDeg;
		a.odometrySumErrorDeg += eo * kDeg;
		if (r.stdDphi > 0)
		{
			const double z = e / r.stdDphi;
			sumSquaredNormalized += z * z;
			absNormalized.push_back(std::abs(z));
			if (std::abs(z) > 3) a.beyond3Sigma++;
		}
	}
	if (a.count == 0) return a;
	const double n = static_cast<double>(a.count);
	a.medianAbsErrorDeg = median(absError);
	a.rmsErrorDeg = std::sqrt(sumSquared / n) * kDeg;
	a.medianPredictedStdDeg = median(stds);
	a.odometryMedianAbsErrorDeg = median(absOdometry);
	a.odometryRmsErrorDeg = std::sqrt(sumSquaredOdometry / n) * kDeg;
	if (!absNormalized.empty())
	{
		a.rmsNormalizedError = std::sqrt(sumSquaredNormalized / static_cast<double>(absNormalized.size()));
		a.medianAbsNormalizedError = median(absNormalized);
	}
	return a;
}

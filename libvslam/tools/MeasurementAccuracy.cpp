#include <libvslam/eval/Median.h>
#include <libvslam/tools/MeasurementAccuracy.h>

#include <algorithm>
#include <cmath>

namespace vslam
{
namespace
{
struct ErrorList
{
	std::vector<double> position, heading, neesSigmaVis, neesItsNoise;
	size_t beyond = 0, beyondItsNoise = 0;

	MeasurementErrorStats stats() const
	{
		MeasurementErrorStats s;
		s.count = position.size();
		s.medianPosition = median(position);
		s.medianHeadingDeg = median(heading) * 180 / M_PI;
		double sp = 0, sh = 0;
		for (size_t i = 0; i < position.size(); i++) sp += position[i] * position[i], sh += heading[i] * heading[i];
		s.rmsPosition = s.count ? std::sqrt(sp / s.count) : 0;
		s.rmsHeadingDeg = s.count ? std::sqrt(sh / s.count) * 180 / M_PI : 0;
		s.beyond3Sigma = beyond;
		s.beyond3SigmaOfItsNoise = beyondItsNoise;
		s.medianNeesSigmaVis = median(neesSigmaVis);
		s.medianNeesItsNoise = median(neesItsNoise);
		return s;
	}
};
}  // namespace

std::optional<se2::Pose> trueLandmarkMeasurement(const Trajectory& truth, double t, double tCreated)
{
	constexpr double kMaxGap = 1.0;  // s between ground-truth samples
	const auto now = interpolate(truth, t, kMaxGap);
	const auto frame = interpolate(truth, tCreated, kMaxGap);
	if (!now || !frame) return std::nullopt;
	return se2::between(*now, *frame);
}

namespace
{
bool beyondThreeOf(const se2::Pose& z, const se2::Pose& truth, const Eigen::Vector3d& std)
{
	const Eigen::Vector3d e = se2::difference(z, truth);
	return (e.cwiseAbs().array() > 3 * std.array()).any();
}
}  // namespace

bool beyondThreeSigma(
	const se2::Pose& z, const se2::Pose& truth, const CMeasurementExtractor::TVisualOptions& sigma)
{
	return beyondThreeOf(z, truth, {sigma.std_dx, sigma.std_dy, sigma.std_dphi});
}

Eigen::Vector3d measurementStd(const LandmarkMeasurementRecord& m, const CMeasurementExtractor::TVisualOptions& sigma)
{
	const double k2 = sigma.predicted_cov_scale * sigma.predicted_cov_scale;
	const auto sq = [](double v) { return v * v; };
	return {std::sqrt(sq(sigma.std_dx) + k2 * sq(m.predictedStdX)), std::sqrt(sq(sigma.std_dy) + k2 * sq(m.predictedStdY)),
		std::sqrt(sq(sigma.std_dphi) + k2 * sq(m.predictedStdPhi))};
}

double normalizedSquaredError(const se2::Pose& z, const se2::Pose& truth, const Eigen::Vector3d& std)
{
	return (se2::difference(z, truth).array() / std.array()).square().sum();
}

bool beyondThreeSigmaOfItsNoise(
	const LandmarkMeasurementRecord& m, const se2::Pose& truth, const CMeasurementExtractor::TVisualOptions& sigma)
{
	return beyondThreeOf(m.z, truth, measurementStd(m, sigma));
}

MeasurementAccuracy evaluateMeasurements(const std::vector<LandmarkMeasurementRecord>& measurements,
	const std::map<int64_t, double>& creationTimes, const Trajectory& truth,
	const CMeasurementExtractor::TVisualOptions& sigma, const CPreFilter::TOptions& prefilter)
{
	const CPreFilter filter(prefilter);
	const Eigen::Vector3d sigmaVisStd(sigma.std_dx, sigma.std_dy, sigma.std_dphi);
	MeasurementAccuracy out;
	ErrorList all, accepted;
	for (const auto& m : measurements)
	{
		out.measurements++;
		const auto created = creationTimes.find(m.landmarkID);
		const auto truthOfIt =
			created == creationTimes.end() ? std::nullopt : trueLandmarkMeasurement(truth, m.t, created->second);
		if (!truthOfIt)
		{
			out.withoutTruth++;
			continue;
		}
		const se2::Pose expected = *truthOfIt;
		const Eigen::Vector3d e = se2::difference(m.z, expected);
		const bool beyond = beyondThreeSigma(m.z, expected, sigma);
		const Eigen::Vector3d itsStd = measurementStd(m, sigma);
		const bool beyondItsNoise = beyondThreeOf(m.z, expected, itsStd);
		const bool ok = filter.check(m.ProjErrRMS, m.NPoints, m.Slope) == CPreFilter::Verdict::Accepted;
		out.errors.push_back({m, expected, e, ok, beyond, beyondItsNoise});
		for (ErrorList* list : {&all, &accepted})
		{
			if (list == &accepted && !ok) continue;
			list->position.push_back(std::hypot(e[0], e[1]));
			list->heading.push_back(std::abs(e[2]));
			list->beyond += beyond;
			list->beyondItsNoise += beyondItsNoise;
			list->neesSigmaVis.push_back(normalizedSquaredError(m.z, expected, sigmaVisStd));
			list->neesItsNoise.push_back(normalizedSquaredError(m.z, expected, itsStd));
		}
	}
	out.all = all.stats();
	out.accepted = accepted.stats();
	return out;
}
}  // namespace vslam

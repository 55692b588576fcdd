#pragma once
/** \file MeasurementAccuracy.h
 * How right the front-end's landmark measurements are, against a ground-
 * truth robot path: a landmark's frame is the robot pose of the image it
 * was created from, so a measurement of landmark L at time t should be
 * truth(t_created(L)) seen from truth(t). Reports the errors of all
 * measurements and of those the pre-filter accepts, and the share of
 * accepted ones beyond 3 sigma of the filter's Sigma_vis in any component
 * (the "false recognition" criterion), which a wrong landmark ID or a
 * badly reconstructed landmark produces. Where the filter weighs each
 * measurement by its predicted covariance ([vslam_visual]
 * predicted_cov_scale), also the share beyond 3 sigma of the noise it
 * actually gives the measurement: the outliers its model cannot absorb.
 */
#include <libvslam/filter/CMeasurementExtractor.h>
#include <libvslam/filter/CPreFilter.h>
#include <libvslam/io/Trajectory.h>

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace vslam
{
struct LandmarkMeasurementRecord
{
	double t = 0;  //!< UNIX s
	int64_t landmarkID = -1;
	se2::Pose z;  //!< measured landmark pose in the robot frame
	double ProjErrRMS = 0;
	uint32_t NPoints = 0;
	double Slope = 0;
	double Height = 0;  //!< m (CObservationVisualLandmark::Height)
	/** Predicted std of dx, dy (m) and dtheta (rad) from the pose solve
	 * (0: not known). */
	double predictedStdX = 0, predictedStdY = 0, predictedStdPhi = 0;
	double SlopeStd = 0;  //!< predicted std of Slope (rad; 0: not known)
};

struct MeasurementErrorStats
{
	size_t count = 0;
	double medianPosition = 0, medianHeadingDeg = 0;  //!< |error|
	double rmsPosition = 0, rmsHeadingDeg = 0;
	size_t beyond3Sigma = 0;  //!< any component beyond 3 sigma of Sigma_vis
	/** Any component beyond 3 sigma of the measurement's own noise in the
	 * filter (measurementStd); equals beyond3Sigma without weighting. */
	size_t beyond3SigmaOfItsNoise = 0;
	/** Median over the measurements of e^T D^-1 e, the error normalized by
	 * the diagonal noise D: of Sigma_vis, and of measurementStd. With 3
	 * degrees of freedom it is 2.37 where the noise is right, less where it
	 * is larger than the errors. */
	double medianNeesSigmaVis = 0, medianNeesItsNoise = 0;
	double shareBeyond3Sigma() const { return count ? double(beyond3Sigma) / count : 0.0; }
	double shareBeyond3SigmaOfItsNoise() const { return count ? double(beyond3SigmaOfItsNoise) / count : 0.0; }
};

struct MeasurementError
{
	LandmarkMeasurementRecord measurement;
	se2::Pose expected;  //!< the truth
	Eigen::Vector3d error;  //!< measured - expected (x, y, phi)
	bool accepted = false;  //!< by the pre-filter
	bool beyond3Sigma = false;
	bool beyond3SigmaOfItsNoise = false;
};

struct MeasurementAccuracy
{
	size_t measurements = 0, withoutTruth = 0;
	MeasurementErrorStats all, accepted;
	std::vector<MeasurementError> errors;  //!< those with truth, in input order
};

/** The true measurement at time t of a landmark created at tCreated: the
 * robot's true pose at creation (the landmark frame) seen from its true
 * pose at t. nullopt where the truth has no pose (outside it, or across a
 * gap over 1 s). */
std::optional<se2::Pose> trueLandmarkMeasurement(const Trajectory& truth, double t, double tCreated);

/** True if measurement z is more than 3 sigma of Sigma_vis from the truth
 * in x, y or heading. */
bool beyondThreeSigma(const se2::Pose& z, const se2::Pose& truth, const CMeasurementExtractor::TVisualOptions& sigma);

/** The std of dx, dy and dtheta the filter gives measurement m: the square
 * root of the diagonal of Sigma_vis + predicted_cov_scale^2 x its
 * predicted covariance (CMeasurementExtractor::extract). */
Eigen::Vector3d measurementStd(const LandmarkMeasurementRecord& m, const CMeasurementExtractor::TVisualOptions& sigma);

/** e^T D^-1 e, e the error of z against the truth, D = diag(std^2). */
double normalizedSquaredError(const se2::Pose& z, const se2::Pose& truth, const Eigen::Vector3d& std);

/** True if m is more than 3 of its measurementStd from the truth in x, y or
 * heading. */
bool beyondThreeSigmaOfItsNoise(
	const LandmarkMeasurementRecord& m, const se2::Pose& truth, const CMeasurementExtractor::TVisualOptions& sigma);

MeasurementAccuracy evaluateMeasurements(const std::vector<LandmarkMeasurementRecord>& measurements,
	const std::map<int64_t, double>& creationTimes, const Trajectory& truth,
	const CMeasurementExtractor::TVisualOptions& sigma, const CPreFilter::TOptions& prefilter);
}  // namespace vslam

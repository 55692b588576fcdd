#pragma once
/** \file MeasurementUpdate.h
 * Generic per-particle work on one landmark measurement: evaluation
 * (innovation, its covariance including the landmark's own uncertainty,
 * Gaussian log-density and NIS) and the landmark's Kalman update. */
#include <libvslam/models/CLandmarkModel.h>

namespace vslam
{
struct MeasurementEvaluation
{
	VecN innovation;
	/** Innovation covariance S = R + H_l P H_l^T (+ H_s C H_s^T). */
	MatN S;
	MatN H_landmark;
	/** S^-1 (valid if gaussian.valid). */
	MatN Sinv;
	GaussianEval gaussian;
};

/** Evaluates measurement m of landmark l from robot pose s. With
 * robotPoseCov (covariance of s, in the global frame), S also includes the
 * robot-pose uncertainty: the predictive distribution before sampling. */
MeasurementEvaluation evaluateMeasurement(
	const CLandmarkModel& model, const se2::Pose& s, const LandmarkEstimate& l,
	const LandmarkMeasurement& m,
	const Eigen::Matrix3d* robotPoseCov = nullptr);

/** The landmark's Kalman update with an evaluated measurement. For pose
 * landmarks h is linear in the landmark given s, so this update is exact. */
void kalmanUpdate(LandmarkEstimate& l, const MeasurementEvaluation& e);

}  // namespace vslam

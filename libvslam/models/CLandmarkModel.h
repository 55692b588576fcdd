#pragma once
/** \file CLandmarkModel.h
 * The measurement model of one landmark kind behind one small interface:
 * prediction h(s, l) with both Jacobians, innovation, landmark
 * initialization (inverse model) and the dual proposal (robot poses
 * explaining a measurement, for the mixture proposal). The generic Kalman
 * update and likelihood built on it live in MeasurementUpdate.h.
 */
#include <libvslam/models/DualProposal.h>
#include <libvslam/models/LandmarkTypes.h>

namespace vslam
{
/** h(s, l) and its Jacobians at one robot pose and landmark mean. */
struct MeasurementPrediction
{
	VecN zhat;
	MatN H_robot;  //!< dim x 3: d h / d s (fits the 3x3 capacity)
	MatN H_landmark;  //!< dim x dim: d h / d l
};

class CLandmarkModel
{
   public:
	virtual ~CLandmarkModel() = default;

	virtual LandmarkKind kind() const = 0;

	/** Predicted measurement of landmark l from robot pose s. */
	virtual MeasurementPrediction predict(
		const se2::Pose& s, const LandmarkEstimate& l,
		const LandmarkMeasurement& m) const = 0;

	/** z - zhat, with the angular component wrapped to (-pi, pi]. */
	virtual VecN innovation(
		const LandmarkMeasurement& m, const VecN& zhat) const = 0;

	/** A new landmark seen from robot pose s (inverse model, covariance from
	 * the measurement noise; with robotPoseCov, also from the uncertainty of
	 * s, in the global frame). */
	LandmarkEstimate initialize(
		const se2::Pose& s, const LandmarkMeasurement& m,
		const Eigen::Matrix3d* robotPoseCov = nullptr) const;

	/** d (landmark state) / d s of the inverse model at s, z. */
	virtual MatN inverseJacobianRobot(
		const se2::Pose& s, const LandmarkMeasurement& m) const = 0;

	/** The distribution of robot poses that explain measurement m of
	 * landmark l (see DualProposal.h). */
	virtual CDualProposal dualProposal(
		const LandmarkEstimate& l, const LandmarkMeasurement& m,
		const HeadingPrior& headingPrior) const = 0;

   protected:
	/** Inverse model from an exactly known pose s. */
	virtual LandmarkEstimate initializeFromMeasurement(
		const se2::Pose& s, const LandmarkMeasurement& m) const = 0;
};

/** Pose landmarks: h(s, l) = l (-) s, the landmark frame seen from s. */
class CPoseLandmarkModel : public CLandmarkModel
{
   public:
	LandmarkKind kind() const override { return LandmarkKind::Pose; }
	MeasurementPrediction predict(
		const se2::Pose& s, const LandmarkEstimate& l,
		const LandmarkMeasurement& m) const override;
	VecN innovation(const LandmarkMeasurement& m, const VecN& zhat) const override;
	MatN inverseJacobianRobot(
		const se2::Pose& s, const LandmarkMeasurement& m) const override;
	CDualProposal dualProposal(
		const LandmarkEstimate& l, const LandmarkMeasurement& m,
		const HeadingPrior& headingPrior) const override;

   protected:
	LandmarkEstimate initializeFromMeasurement(
		const se2::Pose& s, const LandmarkMeasurement& m) const override;
};

/** Point landmarks: h(s, l) = (range, bearing) of point l from the sensor
 * at s (+) sensorPose. */
class CPointLandmarkModel : public CLandmarkModel
{
   public:
	LandmarkKind kind() const override { return LandmarkKind::Point; }
	MeasurementPrediction predict(
		const se2::Pose& s, const LandmarkEstimate& l,
		const LandmarkMeasurement& m) const override;
	VecN innovation(const LandmarkMeasurement& m, const VecN& zhat) const override;
	MatN inverseJacobianRobot(
		const se2::Pose& s, const LandmarkMeasurement& m) const override;
	CDualProposal dualProposal(
		const LandmarkEstimate& l, const LandmarkMeasurement& m,
		const HeadingPrior& headingPrior) const override;

   protected:
	LandmarkEstimate initializeFromMeasurement(
		const se2::Pose& s, const LandmarkMeasurement& m) const override;
};

/** The model for a landmark kind (static instances, stateless). */
const CLandmarkModel& landmarkModel(LandmarkKind kind);

}  // namespace vslam

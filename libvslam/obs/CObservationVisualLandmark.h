#pragma once
/** \file CObservationVisualLandmark.h
 * A visual measurement emitted by the front-end: landmark n was recognized in
 * the current image, and the landmark frame lies at the relative pose
 * (dx, dy, dtheta) in the robot frame (x forward, y left, origin on the floor
 * below the drive-wheel axis), with the paper's three quality statistics
 * and (version 1) the covariance the pose solve predicts for it, (version 2)
 * the robot's height above the landmark frame that the solve implies,
 * (version 3) the std of Slope that the solve predicts.
 */
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <cstdint>

namespace vslam
{
class CObservationVisualLandmark : public mrpt::obs::CObservation
{
	DEFINE_SERIALIZABLE(CObservationVisualLandmark, vslam)

   public:
	static constexpr const char* kDefaultLabel = "CAMERA";
	CObservationVisualLandmark() { sensorLabel = kDefaultLabel; }

	/** ID of the recognized landmark, as issued by its creation event. */
	int64_t landmarkID{-1};
	/** Pose of the landmark frame relative to the robot frame. */
	mrpt::poses::CPose2D relPose;
	/** RMS reprojection error of the pose solve (pixels). */
	double ProjErrRMS{0};
	/** Number of features matched between the image and the landmark. */
	uint32_t NPoints{0};
	/** Robot tilt implied by the 6-DOF solution (rad; ~0 on a level floor). */
	double Slope{0};
	/** Std of Slope as the pose solve predicts it from its inliers' geometry
	 * and pixel error (rad; infinite: degenerate). 0: not known (rawlogs of
	 * serialization versions 0-2, other front-ends). */
	double SlopeStd{0};
	/** Height of the robot frame above the landmark frame implied by the
	 * 6-DOF solution (m; ~0 on a level floor, whatever the landmark's scale:
	 * both frames are the robot's on the floor). 0 in rawlogs of
	 * serialization versions 0-1. */
	double Height{0};
	/** Camera pose on the robot (informational: relPose is already in the
	 * robot frame). */
	mrpt::poses::CPose3D sensorPoseOnRobot;
	/** Covariance of relPose (dx, dy, dtheta) as the front-end's pose solve
	 * predicts it from the geometry of its inliers and their pixel error
	 * alone (not the landmark's own error). All zero: not known (rawlogs
	 * of serialization version 0, other front-ends). */
	mrpt::math::CMatrixDouble33 relPoseCov;

	void getSensorPose(mrpt::poses::CPose3D& out) const override
	{
		out = sensorPoseOnRobot;
	}
	void setSensorPose(const mrpt::poses::CPose3D& p) override
	{
		sensorPoseOnRobot = p;
	}
	void getDescriptionAsText(std::ostream& o) const override;

	bool exportTxtSupported() const override { return true; }
	std::string exportTxtHeader() const override;
	std::string exportTxtDataRow() const override;
};

}  // namespace vslam

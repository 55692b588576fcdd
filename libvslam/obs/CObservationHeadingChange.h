#pragma once
/** \file CObservationHeadingChange.h
 * The robot's heading change between two images of one camera, measured by
 * the front-end from the features the images share (frontend/HeadingChange.h):
 * a visual gyro the filter fuses into the wheel odometry between the two
 * images ([vslam_heading_change]). Emitted with the later image, at its
 * timestamp; previousTimestamp is the earlier image's.
 */
#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose3D.h>

#include <cstdint>

namespace vslam
{
class CObservationHeadingChange : public mrpt::obs::CObservation
{
	DEFINE_SERIALIZABLE(CObservationHeadingChange, vslam)

   public:
	/** Default label "<camera label>_HEADING": its own rawlog-edit columns. */
	static constexpr const char* kDefaultLabel = "CAMERA_HEADING";
	CObservationHeadingChange() { sensorLabel = kDefaultLabel; }

	/** The earlier image's timestamp (the change is from then to timestamp). */
	mrpt::Clock::time_point previousTimestamp{};
	/** Heading change of the robot, rad (counter-clockwise positive). */
	double dphi{0};
	/** Its std as the estimate predicts it, rad. */
	double stdDphi{0};
	/** Feature matches between the two images, and those that fit the motion. */
	uint32_t NMatches{0}, NInliers{0};
	/** RMS distance of the inliers from their epipolar lines, pixels. */
	double rmsPx{0};
	/** Camera pose on the robot. */
	mrpt::poses::CPose3D sensorPoseOnRobot;

	void getSensorPose(mrpt::poses::CPose3D& out) const override { out = sensorPoseOnRobot; }
	void setSensorPose(const mrpt::poses::CPose3D& p) override { sensorPoseOnRobot = p; }
	void getDescriptionAsText(std::ostream& o) const override;

	bool exportTxtSupported() const override { return true; }
	std::string exportTxtHeader() const override;
	std::string exportTxtDataRow() const override;
};

}  // namespace vslam

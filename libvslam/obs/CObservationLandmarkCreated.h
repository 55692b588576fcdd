#pragma once
/** \file CObservationLandmarkCreated.h
 * The front-end created a new visual landmark. Its frame (the "landmark
 * pose" of the paper) is the robot pose at creation; when the front-end
 * builds the landmark from earlier views, landmarkPoseInRobot says where that
 * frame lies relative to the robot pose at this observation's timestamp.
 */
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <cstdint>

namespace vslam
{
class CObservationLandmarkCreated : public mrpt::obs::CObservation
{
	DEFINE_SERIALIZABLE(CObservationLandmarkCreated, vslam)

   public:
	/** Default label "<camera label>_NEW_LANDMARK": tools like rawlog-edit
	 * group by sensor label, and these rows have their own columns. */
	static constexpr const char* kDefaultLabel = "CAMERA_NEW_LANDMARK";
	CObservationLandmarkCreated() { sensorLabel = kDefaultLabel; }

	/** The new landmark's ID (unique among visual landmarks of one run). */
	int64_t landmarkID{-1};
	/** Landmark frame relative to the current robot frame ((0,0,0) when the
	 * landmark frame is the current robot pose). */
	mrpt::poses::CPose2D landmarkPoseInRobot;
	/** Uncertainty of landmarkPoseInRobot (e.g. odometry between the
	 * creating view and now). Zero by default. */
	mrpt::math::CMatrixDouble33 landmarkPoseInRobotCov;
	/** Number of 3-D points kept in the landmark. */
	uint32_t NPoints{0};
	/** Number of images the landmark was built from. */
	uint32_t NViews{0};
	/** Camera pose on the robot. */
	mrpt::poses::CPose3D sensorPoseOnRobot;

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

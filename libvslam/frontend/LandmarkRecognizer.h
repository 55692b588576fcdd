#pragma once
/** \file LandmarkRecognizer.h
 * Recognition of one candidate landmark in an image: descriptor matches
 * between the image and the landmark's points, a RANSAC PnP pose of the
 * camera relative to those points, Levenberg-Marquardt refinement on the
 * inliers, then through the camera mount the paper's measurement: the
 * landmark frame's planar pose (dx, dy, dtheta) in the robot frame, with
 * NPoints (inliers), ProjErrRMS (px) and Slope (robot tilt, rad), and the
 * robot's height in the landmark frame (robotInLandmark.z(), 0 on a level
 * floor, in the measurement's Height for diagnosis).
 * It also predicts how uncertain (dx, dy, dtheta) is: the pose covariance
 * of the least-squares solve (reprojection Jacobian, the inliers' own
 * error) carried to the planar measurement. A few points in a small part
 * of the image leave rotation and sideways translation confusable, and
 * their measurement can be degrees off with a small reprojection error:
 * the paper's statistics do not see it, the predicted uncertainty does.
 */
#include <libvslam/frontend/ImageFeatures.h>
#include <libvslam/frontend/OdometryConsistency.h>
#include <libvslam/frontend/VisualLandmarkModel.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <Eigen/Core>

#include <optional>

namespace vslam
{
struct VisualMeasurement
{
	int64_t landmarkID = 0;
	mrpt::poses::CPose2D landmarkInRobot;  //!< (dx, dy, dtheta)
	/** The 6-DOF solution (planar: x, y, yaw and the camera's height). */
	mrpt::poses::CPose3D robotInLandmark;
	int NPoints = 0;  //!< PnP inliers
	double ProjErrRMS = 0;  //!< px, over the inliers
	double Slope = 0;  //!< tilt of the robot's z axis against the landmark's, rad
	/** The robot's z axis in the landmark frame, its x and y: Slope's
	 * direction (|tilt| = sin Slope). */
	Eigen::Vector2d tilt = Eigen::Vector2d::Zero();
	/** Predicted std of Slope from the pose solve (rad, along the tilt's
	 * direction); infinite where the solve is degenerate. */
	double stdSlope = 0;
	int matches = 0;  //!< descriptor matches before RANSAC
	/** Predicted standard deviations of the measurement: of the position
	 * (sqrt of the largest eigenvalue of its 2x2 covariance, m) and of the
	 * heading (rad). */
	double stdPosition = 0, stdHeading = 0;
	/** The predicted covariance of (dx, dy, dtheta) they come from;
	 * infinite where the solve is degenerate. */
	Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
};

/** Recognizes candidate landmarks in an image by a robust pose solve. */
class CLandmarkRecognizer
{
   public:
	/** INI section [vslam_recognition]. */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		static constexpr const char* kSection = "vslam_recognition";

		int min_inliers = 12;  //!< PnP inliers to accept a pose
		double ransac_px = 3.0;  //!< RANSAC inlier threshold
		int ransac_iterations = 300;  //!< RANSAC's draw budget
		/** Refine the pose with each inlier weighted by its pixel noise plus its
		 * point's depth uncertainty from creation (generalized least squares,
		 * WeightedPoseRefinement.h); the predicted uncertainty is then that
		 * fit's, the structure included. Landmarks keep each point's depth std
		 * (4 bytes per point). A landmark seen from the side is measured
		 * closer without it. */
		bool structure_weighted = true;
		/** A recognition is kept only if it agrees with the same landmark's last
		 * kept one, carried to now by the odometry, when that one is at most
		 * `horizon` old (OdometryConsistency.h; INI key odometry_gate_s, 0: no
		 * test). The tolerances are OdometryConsistency's. A few wrong matches
		 * on a self-similar texture can agree on a pose metres off. */
		TOdometryConsistencyOptions odometry_gate{/* horizon, s */ 5};

		void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
		void saveToConfigFile(mrpt::config::CConfigFileBase& target, const std::string& section) const override;
	};

	/** `matchRatio`: the features' ratio test. */
	CLandmarkRecognizer(const TOptions& options, double matchRatio) : m_options(options), m_matchRatio(matchRatio) {}

	/** The measurement of `landmark` in `image`, if the pose solve finds at
	 * least min_inliers inliers. */
	std::optional<VisualMeasurement> recognize(
		const ImageFeatures& image, const VisualLandmarkModel& landmark, const mrpt::poses::CPose3D& mount) const;

   private:
	TOptions m_options;
	double m_matchRatio;
};
}  // namespace vslam

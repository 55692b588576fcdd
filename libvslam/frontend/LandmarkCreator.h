#pragma once
/** \file LandmarkCreator.h
 * Builds a landmark from a few images taken along the robot's own motion.
 * The camera poses come from odometry and the camera mount (their only
 * source of scale); the image geometry refines them: features are matched
 * across the views, the relative rotation comes from the essential matrix
 * between the first and last view, points are triangulated, then bundle
 * adjustment refines points and poses with odometry as priors on the poses,
 * the scale is reset to the odometry baseline, and points that reproject
 * badly, lie behind a camera, are seen under too small an angle or too far
 * away are dropped. All views are assumed to come from the same camera
 * (the newest view's intrinsics are used).
 */
#include <libvslam/frontend/ImageFeatures.h>
#include <libvslam/frontend/VisualLandmarkModel.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/poses/CPose3D.h>

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vslam
{
/** One image for landmark creation. */
struct CreationView
{
	ImageFeatures features;
	/** The camera in a common frame: robot pose from odometry composed with
	 * the camera mount (camera axes: z forward, x right, y down). */
	mrpt::poses::CPose3D cameraPose;
	double time = 0;
};

struct CreationResult
{
	std::optional<VisualLandmarkModel> landmark;  //!< no value: rejected
	std::string why;  //!< reason for a rejection
	int tracks = 0;  //!< features matched across all views
	int inliers = 0;  //!< points kept
	bool rotationFromImages = false;  //!< essential matrix used (else odometry only)
	/** Refined pose of each view's camera (in `views` order) relative to the
	 * newest camera: X_view = R X_newest + t; filled when built. */
	std::vector<std::pair<Eigen::Matrix3d, Eigen::Vector3d>> refinedPoses;
};

/** Builds landmarks from views along the robot's motion. */
class CLandmarkCreator
{
   public:
	/** INI section [vslam_landmark_creation]. */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		static constexpr const char* kSection = "vslam_landmark_creation";

		int views = 3;  //!< images a landmark is built from (>= 3)
		/** Robot travel between consecutive creation views, m (the baseline
		 * that gives the reconstruction its scale). */
		double min_baseline = 0.15;
		/** A view older than this travel from the newest is dropped, m. */
		double max_baseline = 1.0;
		int min_points = 25;  //!< good 3-D points a landmark needs
		int max_points = 300;  //!< strongest points kept per landmark
		double max_reprojection_px = 2.0;  //!< per view, after refinement
		double min_parallax_deg = 1.0;  //!< widest angle between a point's rays
		double max_depth = 20;  //!< m from the landmark frame
		/** Odometry's uncertainty between creation views, as priors in the
		 * bundle adjustment: heading (deg) and translation relative to the
		 * distance travelled. They keep forward-motion reconstructions from
		 * trading rotation for sideways translation (bas-relief ambiguity). */
		double odometry_sigma_deg = 1.0;
		double odometry_sigma_rel = 0.05;

		void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
		void saveToConfigFile(mrpt::config::CConfigFileBase& target, const std::string& section) const override;
	};

	/** `matchRatio`: the features' ratio test; `keepDepthStd`: landmarks
	 * keep each point's depth std (for a structure-weighted recognition). */
	CLandmarkCreator(const TOptions& options, double matchRatio, bool keepDepthStd)
		: m_options(options), m_matchRatio(matchRatio), m_keepDepthStd(keepDepthStd)
	{
	}

	/** Builds a landmark whose frame is the robot frame of the newest view.
	 * `mount` is the camera pose on the robot (the newest view's). */
	CreationResult create(const std::vector<const CreationView*>& views, const mrpt::poses::CPose3D& mount) const;

   private:
	TOptions m_options;
	double m_matchRatio;
	bool m_keepDepthStd;
};
}  // namespace vslam

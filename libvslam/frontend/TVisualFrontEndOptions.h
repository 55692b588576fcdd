#pragma once
/** \file TVisualFrontEndOptions.h
 * Options of the visual front-end (INI section [vslam_frontend]): SIFT
 * features, landmark creation from a few views along the robot's motion,
 * the landmark database and recognition by a robust pose solve.
 */
#include <libvslam/config/Overrides.h>
#include <libvslam/frontend/OdometryConsistency.h>
#include <mrpt/config/CLoadableOptions.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace vslam
{
struct TVisualFrontEndOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "vslam_frontend";

	// Features (OpenCV SIFT)
	int sift_features = 600;  //!< strongest features kept per image (0: all)
	double sift_contrast_threshold = 0.03;
	/** SIFT's first octave on the image doubled (OpenCV's way: the finest
	 * features), or on the image as it is (false: about half the time, and
	 * fewer features on small images). */
	bool sift_upsample = true;
	/** Gaussian blur (std, px) of the image before SIFT: a cheap camera's
	 * pixel noise and JPEG blocks make fine-scale extrema that do not repeat
	 * from one image to the next; a slight blur takes them out and the
	 * features left match across views far more often (0: none). */
	double sift_denoise_sigma = 0;
	/** Lowe's ratio test between the best and second-best match. */
	double match_ratio = 0.8;

	// Landmark creation
	int creation_views = 3;  //!< images a landmark is built from (>= 3)
	/** Robot travel between consecutive creation views, m (the baseline
	 * that gives the reconstruction its scale). */
	double creation_min_baseline = 0.15;
	/** A view older than this travel from the newest is dropped, m. */
	double creation_max_baseline = 1.0;
	int creation_min_points = 25;  //!< good 3-D points a landmark needs
	int creation_max_points = 300;  //!< strongest points kept per landmark
	double creation_max_reprojection_px = 2.0;  //!< per view, after refinement
	double creation_min_parallax_deg = 1.0;  //!< widest angle between a point's rays
	double creation_max_depth = 20;  //!< m from the landmark frame
	/** Odometry's uncertainty between creation views, as priors in the
	 * bundle adjustment: heading (deg) and translation relative to the
	 * distance travelled. They keep forward-motion reconstructions from
	 * trading rotation for sideways translation (bas-relief ambiguity). */
	double creation_odometry_sigma_deg = 1.0;
	double creation_odometry_sigma_rel = 0.05;

	/** Refine each landmark's scale from its later sightings against the
	 * odometry between them (LandmarkScaleTrack.h). */
	bool scale_refinement = true;
	/** The odometry's translation noise, m/sqrt(m) travelled; 0: the
	 * motion model's sigma_T ([vslam_motion_model] of the same INI), so
	 * the two cannot disagree by oversight. The scale track takes this
	 * noise's mean share out of each odometry displacement, so it should
	 * be the odometry's true noise: one stated too large makes landmarks
	 * too small. */
	double scale_odometry_sigma = 0;

	// Database and recognition
	/** A landmark is a candidate when this many image features vote for it. */
	int recognition_min_votes = 10;
	int recognition_max_candidates = 5;  //!< candidates tried per image
	int recognition_min_inliers = 12;  //!< PnP inliers to accept a pose
	double recognition_ransac_px = 3.0;  //!< RANSAC inlier threshold
	int recognition_ransac_iterations = 300;  //!< RANSAC's draw budget
	/** Refine the pose with each inlier weighted by its pixel noise plus its
	 * point's depth uncertainty from creation (generalized least squares,
	 * WeightedPoseRefinement.h); the predicted uncertainty is then that
	 * fit's, the structure included. Landmarks keep each point's depth std
	 * (4 bytes per point). */
	bool recognition_structure_weighted = false;
	/** Whether landmarks keep each point's depth std. */
	bool keepsDepthStd() const { return recognition_structure_weighted; }
	/** A recognition is kept only if it agrees with the same landmark's last
	 * kept one, carried to now by the odometry, when that one is at most
	 * `horizon` old (OdometryConsistency.h; INI key recognition_odometry_gate_s,
	 * 0: no test). The tolerances are OdometryConsistency's. */
	TOdometryConsistency recognition_odometry_gate;
	/** The descriptor index (DescriptorIndex.h): "flann" (OpenCV FLANN randomized k-d trees,
	 * bounded checks: cost per query nearly independent of the map size)
	 * or "bbf" (k-d trees with leaf buckets searched best bin first, a
	 * bounded number of codes compared). */
	std::string search_index = "flann";
	/** flann: randomized trees per level, and leaves checked per query and level. */
	int search_checks = 32;
	/** bbf: codes compared per query and level (whole leaves of 8). */
	int search_bbf_compared = 128;
	/** The k-d tree votes in a random projection of the descriptors to this
	 * many dimensions (signed bytes; 128: no projection). Candidates are
	 * then verified with the stored descriptors. */
	int search_dims = 16;
	/** How descriptors are stored and matched (DescriptorCodec.h): float,
	 * uint8 (128 bytes), uint4 (64 bytes, square-root scale) or projected
	 * (descriptor_dims signed bytes). */
	std::string descriptor_storage = "uint8";
	int descriptor_dims = 32;

	// Heading change between consecutive images (HeadingChange.h)
	/** Measure the robot's heading change from each image to the camera's
	 * previous one and emit it (CObservationHeadingChange) for the filter to
	 * fuse into the odometry ([vslam_heading_change]). Not in the paper. */
	bool heading_change = false;
	int heading_change_min_inliers = 20;  //!< matches that must fit the motion
	double heading_change_inlier_px = 1.5;  //!< epipolar distance of an inlier, px

	// Map bounding
	/** Most landmarks kept (0: no limit); beyond it the least useful go. */
	int max_landmarks = 0;
	/** A landmark expected in view (its frame within the camera's reach)
	 * but not recognized this many times in a row is removed (0: never). */
	int prune_after_misses = 0;

	// Calibration overrides for data sets without it (0: from the images)
	double fx = 0, fy = 0, cx = 0, cy = 0;

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& source, const std::string& section) override;
	/** Sets scale_odometry_sigma to the motion model's sigma_T if it is 0. */
	void takeOdometryNoiseFrom(double motionModelSigmaT);
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& target, const std::string& section) const override;
};

/** The [vslam_frontend] options of an INI file ("" for none) with `--set`
 * overrides, strictly (unknown keys and bad values are ConfigError naming
 * the file), with the odometry noise of its [vslam_motion_model] where
 * scale_odometry_sigma is 0. Used by the apps that run the front-end alone. */
TVisualFrontEndOptions loadFrontEndOptions(
	const std::string& iniFile, const std::vector<config::Override>& overrides);
}  // namespace vslam

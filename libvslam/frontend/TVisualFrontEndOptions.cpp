#include <libvslam/config/ConfigError.h>
#include <libvslam/config/KeyValidation.h>
#include <libvslam/config/StrictRead.h>
#include <libvslam/frontend/TVisualFrontEndOptions.h>
#include <libvslam/models/CMotionModel.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <vector>

using namespace vslam;
using namespace vslam::config;

void TVisualFrontEndOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	const auto readCount = [&](const char* key, int value, double lo, double hi) {
		return static_cast<int>(readInt(c, s, key, value, Range::closed(lo, hi)));
	};
	sift_features = readCount("sift_features", sift_features, 0, 100000);
	sift_contrast_threshold =
		readDouble(c, s, "sift_contrast_threshold", sift_contrast_threshold, Range::closed(0, 1));
	sift_upsample = readBool(c, s, "sift_upsample", sift_upsample);
	sift_denoise_sigma = readDouble(c, s, "sift_denoise_sigma", sift_denoise_sigma, Range::closed(0, 5));
	match_ratio = readDouble(c, s, "match_ratio", match_ratio, {0, 1, false, true});
	creation_views = readCount("creation_views", creation_views, 3, 10);
	creation_min_baseline =
		readDouble(c, s, "creation_min_baseline", creation_min_baseline, Range::positive());
	creation_max_baseline =
		readDouble(c, s, "creation_max_baseline", creation_max_baseline, Range::positive());
	creation_min_points = readCount("creation_min_points", creation_min_points, 6, 100000);
	creation_max_points = readCount("creation_max_points", creation_max_points, 6, 100000);
	creation_max_reprojection_px = readDouble(
		c, s, "creation_max_reprojection_px", creation_max_reprojection_px, Range::positive());
	creation_min_parallax_deg =
		readDouble(c, s, "creation_min_parallax_deg", creation_min_parallax_deg, Range::closed(0, 90));
	creation_max_depth = readDouble(c, s, "creation_max_depth", creation_max_depth, Range::positive());
	creation_odometry_sigma_deg =
		readDouble(c, s, "creation_odometry_sigma_deg", creation_odometry_sigma_deg, Range{0, 90, false, true});
	creation_odometry_sigma_rel =
		readDouble(c, s, "creation_odometry_sigma_rel", creation_odometry_sigma_rel, Range{0, 10, false, true});
	scale_refinement = readBool(c, s, "scale_refinement", scale_refinement);
	scale_odometry_sigma =
		readDouble(c, s, "scale_odometry_sigma", scale_odometry_sigma, Range::closed(0, 10));
	recognition_min_votes = readCount("recognition_min_votes", recognition_min_votes, 1, 100000);
	recognition_max_candidates =
		readCount("recognition_max_candidates", recognition_max_candidates, 1, 1000);
	recognition_min_inliers = readCount("recognition_min_inliers", recognition_min_inliers, 6, 100000);
	recognition_ransac_px =
		readDouble(c, s, "recognition_ransac_px", recognition_ransac_px, Range::positive());
	recognition_ransac_iterations =
		readCount("recognition_ransac_iterations", recognition_ransac_iterations, 1, 100000);
	recognition_structure_weighted = readBool(c, s, "recognition_structure_weighted", recognition_structure_weighted);
	auto& gate = recognition_odometry_gate;
	gate.horizon = readDouble(c, s, "recognition_odometry_gate_s", gate.horizon, Range::nonNegative());
	search_index = readWord(c, s, "search_index", search_index, {"flann", "bbf"});
	search_checks = readCount("search_checks", search_checks, 1, 100000);
	search_bbf_compared = readCount("search_bbf_compared", search_bbf_compared, 1, 100000000);
	search_dims = readCount("search_dims", search_dims, 4, 128);
	descriptor_storage = readWord(c, s, "descriptor_storage", descriptor_storage, {"float", "uint8", "uint4", "projected"});
	descriptor_dims = readCount("descriptor_dims", descriptor_dims, 4, 128);
	heading_change = readBool(c, s, "heading_change", heading_change);
	heading_change_min_inliers = readCount("heading_change_min_inliers", heading_change_min_inliers, 5, 100000);
	heading_change_inlier_px =
		readDouble(c, s, "heading_change_inlier_px", heading_change_inlier_px, Range::positive());
	max_landmarks = readCount("max_landmarks", max_landmarks, 0, 1e9);
	prune_after_misses = readCount("prune_after_misses", prune_after_misses, 0, 1e9);
	fx = readDouble(c, s, "fx", fx, Range::nonNegative());
	fy = readDouble(c, s, "fy", fy, Range::nonNegative());
	cx = readDouble(c, s, "cx", cx, Range::nonNegative());
	cy = readDouble(c, s, "cy", cy, Range::nonNegative());
	if (creation_max_baseline < creation_min_baseline)
		throw ConfigError("[" + s + "] creation_max_baseline must be >= creation_min_baseline");
	if (creation_max_points < creation_min_points)
		throw ConfigError("[" + s + "] creation_max_points must be >= creation_min_points");
	if ((fx > 0) != (fy > 0))
		throw ConfigError("[" + s + "] fx and fy must be given together");
}

void TVisualFrontEndOptions::takeOdometryNoiseFrom(double motionModelSigmaT)
{
	if (scale_odometry_sigma == 0) scale_odometry_sigma = motionModelSigmaT;
}

void TVisualFrontEndOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "sift_features", sift_features, 30, 10, "Strongest SIFT features kept per image (0: all)");
	c.write(s, "sift_contrast_threshold", sift_contrast_threshold, 30, 10, "SIFT contrast threshold");
	c.write(s, "sift_denoise_sigma", sift_denoise_sigma, 30, 10,
		"Gaussian blur of the image before SIFT against pixel noise [px std] (0: none)");
	c.write(s, "sift_upsample", sift_upsample, 30, 10,
		"SIFT's first octave on the image doubled (true: finest features) or as it is (false: about 2x faster)");
	c.write(s, "match_ratio", match_ratio, 30, 10, "Ratio test: best / second-best distance below this");
	c.write(s, "creation_views", creation_views, 30, 10, "Images a new landmark is built from (>= 3)");
	c.write(s, "creation_min_baseline", creation_min_baseline, 30, 10, "Robot travel between creation views [m]");
	c.write(s, "creation_max_baseline", creation_max_baseline, 30, 10, "Views older than this travel are dropped [m]");
	c.write(s, "creation_min_points", creation_min_points, 30, 10, "Good 3-D points a landmark needs");
	c.write(s, "creation_max_points", creation_max_points, 30, 10, "Points kept per landmark at most");
	c.write(s, "creation_max_reprojection_px", creation_max_reprojection_px, 30, 10, "Point reprojection error limit, every view [px]");
	c.write(s, "creation_min_parallax_deg", creation_min_parallax_deg, 30, 10, "Widest angle between a point's rays at least [deg]");
	c.write(s, "creation_max_depth", creation_max_depth, 30, 10, "Points farther from the landmark frame are dropped [m]");
	c.write(s, "creation_odometry_sigma_deg", creation_odometry_sigma_deg, 30, 10, "Odometry heading uncertainty between creation views [deg]");
	c.write(s, "creation_odometry_sigma_rel", creation_odometry_sigma_rel, 30, 10, "Odometry translation uncertainty per distance travelled");
	c.write(s, "scale_refinement", scale_refinement, 30, 10, "Refine landmark scales from later sightings and odometry");
	c.write(s, "scale_odometry_sigma", scale_odometry_sigma, 30, 10, "Odometry translation noise [m/sqrt(m)] (0: [vslam_motion_model] sigma_T)");
	c.write(s, "recognition_min_votes", recognition_min_votes, 30, 10, "Feature votes that make a landmark a candidate");
	c.write(s, "recognition_max_candidates", recognition_max_candidates, 30, 10, "Candidates tried per image");
	c.write(s, "recognition_min_inliers", recognition_min_inliers, 30, 10, "PnP inliers needed to accept a pose");
	c.write(s, "recognition_ransac_px", recognition_ransac_px, 30, 10, "RANSAC inlier threshold [px]");
	c.write(s, "recognition_ransac_iterations", recognition_ransac_iterations, 30, 10, "RANSAC draw budget");
	c.write(s, "recognition_structure_weighted", recognition_structure_weighted, 30, 10,
		"Refine the pose weighting each inlier by its pixel noise plus its point's depth uncertainty from creation (6-DOF solve)");
	c.write(s, "recognition_odometry_gate_s", recognition_odometry_gate.horizon, 30, 10,
		"Reject a pose that disagrees with the landmark's last kept one at most this old, carried by the odometry (by 0.3 m + 10% of its distance, or 10 deg) [s] (0: off)");
	c.write(s, "search_index", search_index, 30, 10, "Descriptor index: flann (bounded checks) | bbf (bounded codes compared)");
	c.write(s, "search_checks", search_checks, 30, 10, "flann: leaves checked per query and level");
	c.write(s, "search_bbf_compared", search_bbf_compared, 30, 10, "bbf: codes compared per query and level (leaves of 8)");
	c.write(s, "search_dims", search_dims, 30, 10, "Dimensions of the projection the k-d tree votes in (128: none)");
	c.write(s, "descriptor_storage", descriptor_storage, 30, 10, "float | uint8 (128 B) | uint4 (64 B) | projected (descriptor_dims B)");
	c.write(s, "descriptor_dims", descriptor_dims, 30, 10, "Dimensions kept by the projected storage");
	c.write(s, "heading_change", heading_change, 30, 10,
		"Measure the heading change from each image to the camera's previous one (for [vslam_heading_change])");
	c.write(s, "heading_change_min_inliers", heading_change_min_inliers, 30, 10,
		"Heading change: feature matches that must fit the motion");
	c.write(s, "heading_change_inlier_px", heading_change_inlier_px, 30, 10,
		"Heading change: epipolar distance of an inlier [px]");
	c.write(s, "max_landmarks", max_landmarks, 30, 10, "Landmarks kept at most (0: no limit)");
	c.write(s, "prune_after_misses", prune_after_misses, 30, 10, "Remove a landmark missed this often in a row when expected (0: never)");
	c.write(s, "fx", fx, 30, 10, "Focal length override [px] (0: from each image)");
	c.write(s, "fy", fy, 30, 10, "Focal length override [px] (0: from each image)");
	c.write(s, "cx", cx, 30, 10, "Principal point override [px] (with fx, fy)");
	c.write(s, "cy", cy, 30, 10, "Principal point override [px] (with fx, fy)");
}

TVisualFrontEndOptions vslam::loadFrontEndOptions(
	const std::string& iniFile, const std::vector<config::Override>& overrides)
{
	const std::string text = iniFile.empty() ? std::string() : config::readIniFile(iniFile);
	TVisualFrontEndOptions options;
	try
	{
		const auto cfg = config::parseIniWithOverrides(text, overrides);
		config::KnownKeys known;
		known.addFromOptions(options, TVisualFrontEndOptions::kSection);
		config::checkNoUnknownKeys(cfg, known, TVisualFrontEndOptions::kSection);
		options.loadFromConfigFile(cfg, TVisualFrontEndOptions::kSection);
		CMotionModel::TOptions motion;
		motion.loadFromConfigFile(cfg, CMotionModel::TOptions::kSection);
		options.takeOdometryNoiseFrom(motion.sigma_T);
	}
	catch (const ConfigError& e)
	{
		throw ConfigError((iniFile.empty() ? std::string("--set") : "'" + iniFile + "'") + ": " + e.what());
	}
	return options;
}

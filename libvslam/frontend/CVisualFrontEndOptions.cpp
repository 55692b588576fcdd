#include <libvslam/config/ConfigError.h>
#include <libvslam/config/IniText.h>
#include <libvslam/config/StrictRead.h>
#include <libvslam/frontend/CVisualFrontEnd.h>
#include <libvslam/models/CMotionModel.h>

using namespace vslam;

namespace
{
/** Where each key of the single [vslam_frontend] section of earlier
 * versions went: {old key, new section, new key}. */
struct MovedKey
{
	const char* oldKey;
	const char* section;
	const char* key;
};
constexpr const char* kOldSection = "vslam_frontend";
const MovedKey kMovedKeys[] = {
	{"sift_features", CFeatureExtractor::TOptions::kSection, "sift_features"},
	{"sift_contrast_threshold", CFeatureExtractor::TOptions::kSection, "sift_contrast_threshold"},
	{"sift_denoise_sigma", CFeatureExtractor::TOptions::kSection, "sift_denoise_sigma"},
	{"match_ratio", CFeatureExtractor::TOptions::kSection, "match_ratio"},
	{"creation_views", CLandmarkCreator::TOptions::kSection, "views"},
	{"creation_min_baseline", CLandmarkCreator::TOptions::kSection, "min_baseline"},
	{"creation_max_baseline", CLandmarkCreator::TOptions::kSection, "max_baseline"},
	{"creation_min_points", CLandmarkCreator::TOptions::kSection, "min_points"},
	{"creation_max_points", CLandmarkCreator::TOptions::kSection, "max_points"},
	{"creation_max_reprojection_px", CLandmarkCreator::TOptions::kSection, "max_reprojection_px"},
	{"creation_min_parallax_deg", CLandmarkCreator::TOptions::kSection, "min_parallax_deg"},
	{"creation_max_depth", CLandmarkCreator::TOptions::kSection, "max_depth"},
	{"creation_odometry_sigma_deg", CLandmarkCreator::TOptions::kSection, "odometry_sigma_deg"},
	{"creation_odometry_sigma_rel", CLandmarkCreator::TOptions::kSection, "odometry_sigma_rel"},
	{"scale_refinement", CLandmarkScaleTrack::TOptions::kSection, "enabled"},
	{"scale_odometry_sigma", CLandmarkScaleTrack::TOptions::kSection, "odometry_sigma"},
	{"recognition_min_votes", CLandmarkDatabase::TOptions::kSection, "min_votes"},
	{"recognition_max_candidates", CLandmarkDatabase::TOptions::kSection, "max_candidates"},
	{"recognition_min_inliers", CLandmarkRecognizer::TOptions::kSection, "min_inliers"},
	{"recognition_ransac_px", CLandmarkRecognizer::TOptions::kSection, "ransac_px"},
	{"recognition_ransac_iterations", CLandmarkRecognizer::TOptions::kSection, "ransac_iterations"},
	{"recognition_structure_weighted", CLandmarkRecognizer::TOptions::kSection, "structure_weighted"},
	{"recognition_odometry_gate_s", CLandmarkRecognizer::TOptions::kSection, "odometry_gate_s"},
	{"search_index", CLandmarkDatabase::TOptions::kSection, "search_index"},
	{"search_checks", CLandmarkDatabase::TOptions::kSection, "search_checks"},
	{"search_bbf_compared", CLandmarkDatabase::TOptions::kSection, "search_bbf_compared"},
	{"search_dims", CLandmarkDatabase::TOptions::kSection, "search_dims"},
	{"descriptor_storage", CLandmarkDatabase::TOptions::kSection, "descriptor_storage"},
	{"descriptor_dims", CLandmarkDatabase::TOptions::kSection, "descriptor_dims"},
	{"max_landmarks", CLandmarkDatabase::TOptions::kSection, "max_landmarks"},
	{"prune_after_misses", CLandmarkDatabase::TOptions::kSection, "prune_after_misses"},
	{"heading_change", CHeadingChangeEstimator::TOptions::kSection, "enabled"},
	{"heading_change_min_inliers", CHeadingChangeEstimator::TOptions::kSection, "min_inliers"},
	{"heading_change_inlier_px", CHeadingChangeEstimator::TOptions::kSection, "inlier_px"},
	{"fx", CImageCalibration::TOptions::kSection, "fx"},
	{"fy", CImageCalibration::TOptions::kSection, "fy"},
	{"cx", CImageCalibration::TOptions::kSection, "cx"},
	{"cy", CImageCalibration::TOptions::kSection, "cy"},
};

/** Every component's options with its section, in the order they are written. */
template <typename Options, typename Visit>
void forEachSection(Options& o, Visit&& visit)
{
	visit(o.features, CFeatureExtractor::TOptions::kSection);
	visit(o.camera, CImageCalibration::TOptions::kSection);
	visit(o.creation, CLandmarkCreator::TOptions::kSection);
	visit(o.scale, CLandmarkScaleTrack::TOptions::kSection);
	visit(o.recognition, CLandmarkRecognizer::TOptions::kSection);
	visit(o.database, CLandmarkDatabase::TOptions::kSection);
	visit(o.heading, CHeadingChangeEstimator::TOptions::kSection);
}
}  // namespace

void CVisualFrontEnd::TOptions::loadFromConfig(const mrpt::config::CConfigFileBase& cfg)
{
	forEachSection(*this, [&](auto& options, const char* section) { options.loadFromConfigFile(cfg, section); });
}

void CVisualFrontEnd::TOptions::saveToConfig(mrpt::config::CConfigFileBase& cfg) const
{
	forEachSection(*this, [&](const auto& options, const char* section) { options.saveToConfigFile(cfg, section); });
}

void CVisualFrontEnd::TOptions::registerKnownKeys(config::KnownKeys& known) const
{
	forEachSection(*this, [&](const auto& options, const char* section) { known.addFromOptions(options, section); });
	for (const auto& m : kMovedKeys) known.addMoved(kOldSection, m.oldKey, m.section, m.key);
}

CVisualFrontEnd::TOptions vslam::loadFrontEndOptions(
	const std::string& iniFile, const std::vector<config::Override>& overrides)
{
	const std::string text = iniFile.empty() ? std::string() : config::readIniFile(iniFile);
	CVisualFrontEnd::TOptions options;
	try
	{
		const auto cfg = config::parseIniWithOverrides(text, overrides);
		config::KnownKeys known;
		options.registerKnownKeys(known);
		// Only the front-end's sections (and the old one) are checked: the
		// INI may hold the whole run's.
		for (const auto& section : known.sections()) config::checkNoUnknownKeys(cfg, known, section);
		config::checkNoUnknownKeys(cfg, known, kOldSection);
		options.loadFromConfig(cfg);
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

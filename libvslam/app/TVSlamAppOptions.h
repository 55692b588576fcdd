#pragma once
/** \file TVSlamAppOptions.h
 * The [vslam] section: what to read, where to write, the random seed.
 * Input files given in the INI are relative to the INI file's folder;
 * output_dir and command-line paths are relative to the working folder.
 */
#include <mrpt/config/CLoadableOptions.h>

#include <cmath>
#include <cstdint>
#include <string>

namespace vslam
{
struct TVSlamAppOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "vslam";

	std::string rawlog_file;
	std::string output_dir = "vslam_out";
	/** -1: seed from the clock (the seed used is written to the summary). */
	int64_t RANDOM_SEED = -1;
	/** Optional ground truth (TUM or rbpf-slam path format) for the
	 * summary's error figures. */
	std::string ground_truth_file;
	/** Optional map to start from (localization in a known map, or map
	 * continuation): vslam's final_map.vslam (landmarks and what the
	 * camera recognizes them by), final_map.txt, or rows 'id x y' (points)
	 * / 'id x y phi' (poses); see io/LandmarkMapFile.h. */
	std::string prior_map_file;
	/** Keep the prior map fixed: no landmark is added, updated or removed. */
	bool localization_only = false;
	/** The start pose is unknown: find it in the prior map (global localization). */
	bool initial_pose_unknown = false;
	/** Uncertainty of map rows that carry no covariance. */
	double prior_map_std_xy = 0.05;  //!< m
	double prior_map_std_phi = 2 * M_PI / 180;  //!< rad (INI: degrees)
	/** Start the filter at the ground-truth pose of the first step (both
	 * trajectories then start at the robot's first pose), instead of
	 * [vslam_particle_filter] initial_x/y/phi_deg. */
	bool initial_pose_from_ground_truth = false;
	/** Process at most this many rawlog steps (0: all). */
	uint64_t max_steps = 0;
	bool show_progress = true;

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& cfg,
		const std::string& section) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& cfg,
		const std::string& section) const override;
};
}  // namespace vslam

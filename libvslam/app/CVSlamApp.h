#pragma once
/** \file CVSlamApp.h
 * The vslam application, used like MRPT's rbpf-slam:
 *
 *   vslam CONFIG.ini [RAWLOG] [--out DIR] [--set SECTION.KEY=VALUE ...]
 *
 * initialize() parses the command line and the INI (with --set overrides,
 * unknown-key checks and strict values); run() streams the rawlog through
 * the filter and writes, step by step and flushed:
 *   log_estimated_path.txt   rbpf-slam's format (step x y z yaw pitch roll t)
 *   estimated_path.tum       the same in TUM format
 *   log_odometry_path.txt    dead reckoning (rbpf-slam's odometry format)
 *   log_filter_steps.txt     ESS, dual share, kidnap test, landmarks, time
 * and at the end (also after an error or Ctrl-C), each atomically:
 *   final_map.txt, final_map.vslam (the whole map, for prior_map_file),
 *   most_likely_path.txt/.tum, pose_graph_path.tum,
 *   run_summary.yaml (also at the start, "status: running").
 * config_used.ini (the effective configuration, which reruns the run) is
 * written at the start. Outputs an earlier run left in the folder are
 * removed first; a failed write is an OutputError (exit 4).
 * main() wraps both with error reporting and exit codes.
 */
#include <libvslam/app/RunOutputFolder.h>
#include <libvslam/app/RunSummary.h>
#include <libvslam/config/KeyValidation.h>
#include <libvslam/config/StrictRead.h>
#include <libvslam/filter/CVSlamParticleFilter.h>
#include <libvslam/frontend/CVisualFrontEnd.h>
#include <libvslam/io/CRawlogReader.h>
#include <libvslam/io/Trajectory.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/config/CLoadableOptions.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace vslam
{
class CVisualFrontEnd;
class CVSlamMap;

class CVSlamApp
{
   public:
	enum ExitCode : int
	{
		kOk = 0,
		kUsage = 1,
		kConfigError = 2,
		kInputError = 3,
		kOtherError = 4,
		kInterrupted = 130
	};

	/** The [vslam] section: what to read, where to write, the random seed.
	 * Input files given in the INI are relative to the INI file's folder;
	 * output_dir and command-line paths are relative to the working folder. */
	struct TOptions : public mrpt::config::CLoadableOptions
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

	/** Parses arguments and configuration; throws ConfigError. Returns
	 * false if there is nothing to run (--help, --version, ...). */
	bool initialize(int argc, const char** argv);
	/** Runs; returns an exit code. Throws InputError on bad data. */
	int run();
	/** initialize() + run() with error messages and exit codes. */
	int main(int argc, const char** argv);

	/** The effective configuration (INI + overrides). */
	mrpt::config::CConfigFileMemory params;
	TOptions appOptions;
	CVSlamParticleFilter::TOptions filterOptions;
	CVisualFrontEnd::TOptions frontEndOptions;  //!< used when the rawlog has images

	static std::string usage();
	/** Every key with its default and documentation, as INI text. */
	static std::string defaultConfigText();
	/** The keys of every vslam section. */
	static config::KnownKeys knownKeys();
	/** Every numeric key with its allowed range (as the options read them). */
	static std::vector<config::NumericKey> numericKeys();

   private:
	struct RunState;
	std::string m_configFile, m_rawlogFile, m_groundTruthFile, m_priorMapFile, m_outputDir;
	bool m_quiet = false;

	void loadConfig(const std::string& file, const std::vector<std::string>& overrides);
	std::string resolveInput(const std::string& path) const;
	/** The ground truth and the prior map, each read if named; throws
	 * InputError naming the key, or ConfigError for a map that cannot serve. */
	struct InputFiles
	{
		Trajectory groundTruth;
		std::shared_ptr<const CVSlamMap> priorMap;
	};
	InputFiles readInputFiles() const;
	/** The filter (and later the front-end) starts from the prior map: fixed
	 * with localization_only, from an unknown pose with initial_pose_unknown. */
	void startFromPriorMap(RunState& r, std::shared_ptr<const CVSlamMap> map, RunSummary& summary) const;
	/** The front-end, with the prior map's visual landmarks (fixed with
	 * localization_only); throws ConfigError if they cannot be used. */
	std::unique_ptr<CVisualFrontEnd> makeFrontEnd(const CVSlamMap* priorMap) const;
	/** Throws ConfigError if images are to be localized (localization_only)
	 * in a map without appearances. */
	void checkImagesCanBeLocalized(const CVSlamMap* priorMap) const;
	void startFromGroundTruth(const Trajectory& groundTruth, bool haveStep, RawlogStep& step);
	std::string effectiveConfigText(uint64_t seed, const std::string& outputDir) const;
	/** Clears the folder, names the run, writes config_used.ini and the
	 * first summary (status: running). */
	void startOutputs(const RunOutputFolder& folder, RunSummary& summary) const;
	void processSteps(RunState& r, CRawlogReader& reader, RawlogStep& step, bool haveStep, RunSummary& summary);
	void processStep(RunState& r, const RawlogStep& step, RunSummary& summary);
	/** Global localization's figures for the summary, after each step. */
	void noteStartPose(const RunState& r, double t, bool foundNow, RunSummary::StartPose& start) const;
	void summarizeReader(const CRawlogReader& reader, const RunState& r, RunSummary& summary) const;
	void writeFinalOutputs(
		const RunOutputFolder& folder, const RunState& r, const Trajectory& groundTruth, RunSummary& summary) const;
	void checkGroundTruthBelongsToTheRun(const RunState& r, const Trajectory& groundTruth, RunSummary& summary) const;
};
}  // namespace vslam

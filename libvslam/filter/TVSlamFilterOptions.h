#pragma once
/** \file TVSlamFilterOptions.h
 * Every option of the filter, one INI section per component:
 *
 *   [vslam_particle_filter]   particle count, resampling, initial pose,
 *                             joint or sequential processing
 *   [vslam_motion_model]      CMotionModel::TOptions
 *   [vslam_likelihood]        CRobustLikelihood::TOptions
 *   [vslam_mixture_proposal]  CMixtureProposal::TOptions
 *   [vslam_kidnap]            CKidnapDetector::TOptions
 *   [vslam_landmarks]         initial landmark covariance, re-initialization
 *   [vslam_visual]            visual measurement noise Sigma_vis
 *   [vslam_range_bearing]     range-bearing measurements
 *   [vslam_heading_change]    heading changes between images, fused into the odometry
 *   [vslam_prefilter]         CPreFilter::TOptions
 *   [vslam_loop_closure]      CLandmarkPoseGraph::TOptions
 */
#include <libvslam/config/KeyValidation.h>
#include <libvslam/filter/CKidnapDetector.h>
#include <libvslam/filter/CMeasurementExtractor.h>
#include <libvslam/filter/CMixtureProposal.h>
#include <libvslam/filter/CPreFilter.h>
#include <libvslam/filter/CSmoothedPose.h>
#include <libvslam/graph/CLandmarkPoseGraph.h>
#include <libvslam/models/CMotionModel.h>
#include <libvslam/models/CRobustLikelihood.h>
#include <mrpt/bayes/CParticleFilter.h>

namespace vslam
{
/** [vslam_particle_filter] */
struct TParticleFilterOptions : public mrpt::config::CLoadableOptions
{
	/** Number of particles (MRPT's key name). */
	uint32_t sampleSize = 200;
	/** Resample when ESS < BETA (MRPT's key name). */
	double BETA = 0.5;
	mrpt::bayes::CParticleFilter::TParticleResamplingAlgorithm
		resamplingMethod = mrpt::bayes::CParticleFilter::prSystematic;
	/** Initial robot pose and its spread (0: all particles on it). */
	se2::Pose initialPose{0, 0, 0};
	double initial_std_xy = 0;  //!< m
	double initial_std_phi = 0;  //!< rad (INI: degrees)

	/** MRPT's particle-filter options (used by CParticleFilter::executeOn). */
	mrpt::bayes::CParticleFilter::TParticleFilterOptions toMrpt() const;

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& cfg,
		const std::string& section) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& cfg,
		const std::string& section) const override;
};

/** [vslam_landmarks] */
struct TLandmarkOptions : public mrpt::config::CLoadableOptions
{
	/** Extra uncertainty of a new visual landmark's frame relative to the
	 * robot pose it is created at (front-end reconstruction error). */
	double init_std_xy = 0.03;  //!< m
	double init_std_phi = 1.0 * M_PI / 180;  //!< rad (INI: degrees)
	/** Before the first landmark is created, collapse the particle cloud
	 * onto its weighted mean, so the map's frame is the best estimate of the
	 * robot's pose at that time instead of the pose of whichever particle's
	 * lineage resampling happens to keep (the map's frame is unobservable
	 * afterwards). No effect with a prior map. */
	bool anchor_first_landmark = true;

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& cfg,
		const std::string& section) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& cfg,
		const std::string& section) const override;
};

struct TVSlamFilterOptions
{
	static constexpr const char* kParticleFilter = "vslam_particle_filter";
	static constexpr const char* kMotionModel = CMotionModel::TOptions::kSection;
	static constexpr const char* kLikelihood = "vslam_likelihood";
	static constexpr const char* kMixture = "vslam_mixture_proposal";
	static constexpr const char* kKidnap = "vslam_kidnap";
	static constexpr const char* kLandmarks = "vslam_landmarks";
	static constexpr const char* kVisual = "vslam_visual";
	static constexpr const char* kRangeBearing = "vslam_range_bearing";
	static constexpr const char* kHeadingChange = "vslam_heading_change";
	static constexpr const char* kPreFilter = "vslam_prefilter";
	static constexpr const char* kLoopClosure = CLandmarkPoseGraph::TOptions::kSection;
	static constexpr const char* kSmoothedPose = CSmoothedPose::TOptions::kSection;

	TParticleFilterOptions pf;
	CMotionModel::TOptions motion;
	CRobustLikelihood::TOptions likelihood;
	CMixtureProposal::TOptions mixture;
	CKidnapDetector::TOptions kidnap;
	TLandmarkOptions landmarks;
	CMeasurementExtractor::TVisualOptions visual;
	CMeasurementExtractor::TRangeBearingOptions rangeBearing;
	CMeasurementExtractor::THeadingChangeOptions headingChange;
	CPreFilter::TOptions prefilter;
	CLandmarkPoseGraph::TOptions loopClosure;
	CSmoothedPose::TOptions smoothedPose;

	/** Reads every section (absent keys keep their defaults). */
	void loadFromConfig(const mrpt::config::CConfigFileBase& cfg);
	/** Writes every section with comments. */
	void saveToConfig(mrpt::config::CConfigFileBase& cfg) const;
	/** Adds every section's keys to `known`. */
	void registerKnownKeys(config::KnownKeys& known) const;
};

}  // namespace vslam

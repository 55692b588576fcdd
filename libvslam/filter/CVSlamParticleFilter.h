#pragma once
/** \file CVSlamParticleFilter.h
 * The vSLAM filter (Karlsson et al. 2005, sections III-C): a particle
 * filter over robot paths, each particle carrying a copy-on-write bank of
 * landmark Kalman filters (3-state pose landmarks, 2-state point landmarks),
 * with the nominal/dual mixture proposal and kidnap recovery.
 *
 * It is an MRPT particle filter: drive it with
 * mrpt::bayes::CParticleFilter::executeOn(filter, action, sf), which calls
 * prediction_and_update_pfStandardProposal() (our mixture proposal runs in
 * that slot), normalizes and resamples with MRPT's methods when
 * ESS < BETA. Tests and benchmarks may call addOdometryIncrement() and
 * processFrame() directly.
 *
 * Odometry is accumulated between frames and sampled once per accumulated
 * increment. See doc/mixture-proposal.md for the weights and the kidnap
 * criterion.
 */
#include <libvslam/config/KeyValidation.h>
#include <libvslam/filter/CKidnapDetector.h>
#include <libvslam/filter/CLandmarkIndex.h>
#include <libvslam/filter/CMeasurementExtractor.h>
#include <libvslam/filter/CMixtureProposal.h>
#include <libvslam/filter/CPreFilter.h>
#include <libvslam/filter/CSmoothedPose.h>
#include <libvslam/filter/CVSlamParticle.h>
#include <libvslam/filter/KnownMeasurement.h>
#include <libvslam/filter/MotionPrior.h>
#include <libvslam/graph/CLandmarkPoseGraph.h>
#include <libvslam/models/CMotionModel.h>
#include <libvslam/models/COdometryAccumulator.h>
#include <libvslam/models/CRobustLikelihood.h>
#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/bayes/CParticleFilterCapable.h>
#include <mrpt/bayes/CParticleFilterData.h>

#include <cstdint>
#include <optional>

namespace mrpt::random
{
class CRandomGenerator;
}

namespace vslam
{
/** Counters over a whole run. */
struct TFilterStats
{
	uint64_t frames = 0;
	uint64_t measurementsUsed = 0;
	/** Measurements of known landmarks no particle explained (outliers). */
	uint64_t rejectedUnexplained = 0;
	uint64_t landmarksCreated = 0;
	uint64_t landmarksCreatedFromMeasurement = 0;
	uint64_t landmarksReinitialized = 0;
	uint64_t duplicateCreations = 0;
	/** Landmarks not placed (first sightings and creations) because the map
	 * is fixed or the start pose not yet found. */
	uint64_t landmarksNotPlaced = 0;
	/** From an unknown start: measurements before the pose was found, left out. */
	uint64_t measurementsWhilePoseUnknown = 0;
	uint64_t kidnapsDetected = 0;
	/** Declared kidnaps another landmark contradicted: the filter went back. */
	uint64_t kidnapsReverted = 0;
	/** Frames whose anchored measurements the filter could not explain
	 * (a relocalization hypothesis was tested). */
	uint64_t unexplainedFrames = 0;
	uint64_t dualParticlesDrawn = 0;
	uint64_t resamplings = 0;
	/** Loop closures: optimizations of the pose graph applied to the
	 * particles, and the measurement edges the gate left out of the latest. */
	uint64_t loopClosures = 0;
	uint64_t loopClosureEdgesLeftOut = 0;
	/** Heading changes between images fused into the odometry, those
	 * outside the gate, and those without their start image as reference
	 * (the first image, after a gap, or after an update in between). */
	uint64_t headingChangesFused = 0, headingChangesGated = 0, headingChangesWithoutReference = 0;
};

/** What happened in the last processed frame (for logs and plots). */
struct TFrameReport
{
	mrpt::Clock::time_point timestamp{};
	size_t measurements = 0;  //!< of known landmarks
	size_t used = 0;
	double explainedFraction = 0;
	/** Support of the relocalization hypothesis under test (0: none). */
	size_t hypothesisSupport = 0;
	/** Kidnapping declared: the filter switched to the hypothesis. */
	bool kidnapDeclared = false;
	/** From an unknown start: the pose was found in this frame. */
	bool poseFound = false;
	/** The last kidnap was contradicted: the filter went back. */
	bool kidnapReverted = false;
	double dualRatio = 0;
	size_t dualParticles = 0;
	double essAfterUpdate = 1;
};

class CVSlamParticleFilter
	: public mrpt::bayes::CParticleFilterData<
		  CVSlamParticle, mrpt::bayes::particle_storage_mode::VALUE>,
	  public mrpt::bayes::CParticleFilterDataImpl<
		  CVSlamParticleFilter,
		  mrpt::bayes::CParticleFilterData<
			  CVSlamParticle,
			  mrpt::bayes::particle_storage_mode::VALUE>::CParticleList>
{
   public:
	/** [vslam_particle_filter] */
	struct TParticleFilterOptions : public mrpt::config::CLoadableOptions
	{
		/** Number of particles (MRPT's key name). Each resampling while the
		 * robot explores moves the cloud's mean by about its spread over the
		 * square root of the count: with the paper's 200 the estimate drifts
		 * off the odometry between landmarks, with 1,000 it stays. */
		uint32_t sampleSize = 1000;
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

	/** Every option of the filter, one INI section per component:
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
	struct TOptions
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

	CVSlamParticleFilter();
	explicit CVSlamParticleFilter(const TOptions& options);

	/** Particles on the initial pose (spread by its std), empty maps. */
	void reset();
	const TOptions& options() const { return m_options; }

	// ---- inputs ---------------------------------------------------------
	/** The message of the InputError the last step threw ("" if none), and
	 * clears it. Run through mrpt::bayes::CParticleFilter::executeOn(), an
	 * InputError arrives wrapped in MRPT's exception type; this tells the
	 * caller it was bad input and why. */
	std::string takeInputError();

	/** Appends one odometry increment; throws InputError if not finite.
	 * `end`, the time of the reading that ends it, if known: a heading
	 * change measured from an image taken then can be fused (the first
	 * image's, or one after an image that brought none). */
	void addOdometryIncrement(
		const se2::Pose& u, std::optional<mrpt::Clock::time_point> end = std::nullopt);
	/** Processes the measurements and creation events of one frame; its
	 * heading change, if any, first corrects the pending odometry. */
	void processFrame(const FrameMeasurements& frame);
	/** Seeds every particle with the same prior map (map continuation,
	 * benchmarks): the bank is shared, O(1) per particle. A `fixed` map is
	 * for localization only: its landmarks are never updated or moved,
	 * and a landmark not in it is never added. */
	void setPriorMap(
		const std::vector<std::pair<LandmarkKey, LandmarkEstimate>>& map,
		mrpt::Clock::time_point t = {}, bool fixed = false);
	bool mapFixed() const { return m_mapFixed; }
	/** Global localization in the prior map: the pose is unknown until the
	 * kidnap test's relocalization hypothesis (dual particles from the
	 * measurements of mapped landmarks) is confirmed; until then no
	 * measurement weighs the cloud and no landmark is placed. Needs a prior
	 * map and [vslam_kidnap] enabled (throws std::logic_error otherwise). */
	void setPoseUnknown();
	bool poseKnown() const { return !m_poseUnknown; }

	// ---- outputs --------------------------------------------------------
	/** Weighted mean pose (circular mean heading), composed with the
	 * odometry accumulated since the last frame. */
	se2::Pose meanPose() const;
	/** Weighted covariance of the particle poses (without pending odometry). */
	Eigen::Matrix3d poseCovariance() const;
	size_t bestParticleIndex() const;
	const CVSlamParticle& particle(size_t i) const { return m_particles.at(i).d; }
	const CLandmarkIndex& landmarkIndex() const { return m_index; }
	const TFilterStats& stats() const { return m_stats; }
	const TFrameReport& lastFrame() const { return m_lastFrame; }
	const CMeasurementExtractor& extractor() const { return m_extractor; }
	const COdometryAccumulator& pendingOdometry() const { return m_odometry; }
	const CKidnapDetector& kidnapDetector() const { return m_kidnap; }
	/** The loop-closure pose graph (nullptr: none, see m_graph). */
	const CLandmarkPoseGraph* loopClosureGraph() const { return m_graph ? &*m_graph : nullptr; }

	// ---- CParticleFilterCapable (overridden to avoid the per-call
	// dynamic_cast of CParticleFilterDataImpl) ------------------------------
	double getW(size_t i) const override { return m_particles.at(i).log_w; }
	void setW(size_t i, double w) override { m_particles.at(i).log_w = w; }
	size_t particlesCount() const override { return m_particles.size(); }
	double normalizeWeights(double* out_max_log_w = nullptr) override;
	double ESS() const override;
	/** MRPT 2.5.8 keeps old weights after resampling (pitfall 1): reset
	 * them here. */
	void performSubstitution(const std::vector<size_t>& indx) override;

   protected:
	void prediction_and_update_pfStandardProposal(
		const mrpt::obs::CActionCollection* action,
		const mrpt::obs::CSensoryFrame* observation,
		const mrpt::bayes::CParticleFilter::TParticleFilterOptions& o) override;

   private:
	TOptions m_options;
	CMotionModel m_motion;
	CRobustLikelihood m_likelihood;
	CMixtureProposal m_mixture;
	CKidnapDetector m_kidnap;
	CMeasurementExtractor m_extractor;
	CLandmarkIndex m_index;
	COdometryAccumulator m_odometry;
	bool m_mapFixed = false;
	bool m_poseUnknown = false;
	TFilterStats m_stats;
	TFrameReport m_lastFrame;
	std::vector<PoseGaussianProposal> m_proposalBuffer;  //!< reused per frame
	mrpt::random::CRandomGenerator& m_rng;
	std::string m_inputError;  //!< see takeInputError()
	/** The loop-closure back-end (none: disabled, prior map, or point
	 * landmarks in the run). */
	std::optional<CLandmarkPoseGraph> m_graph;
	/** The last declared kidnap: when, and the landmarks it made suspect
	 * (what going back undoes). */
	struct LastKidnap
	{
		mrpt::Clock::time_point time;
		std::vector<LandmarkKey> markedSuspect;
	};
	std::optional<LastKidnap> m_lastKidnap;

	void updateWithFrame(const FrameMeasurements& frame);
	/** The frame's measurements of known landmarks, and the first sighting
	 * of each landmark not yet in the map. */
	void splitByLandmark(const FrameMeasurements& frame, std::vector<KnownMeasurement>& known,
		std::vector<const LandmarkMeasurement*>& firstSightings) const;
	/** What the kidnap test makes of the measurements the predicted cloud
	 * explains (their fractions already computed); the best fraction. */
	CKidnapDetector::Verdict kidnapVerdict(mrpt::Clock::time_point t, const std::vector<KnownMeasurement>& known,
		const MotionPrior& mp, double& bestFraction);
	using LandmarksToPlace = std::vector<std::pair<size_t, const LandmarkMeasurement*>>;
	using PlacedLandmarks = std::vector<std::pair<size_t, LandmarkMeasurement>>;
	/** Creates the first-sighted and front-end-created landmarks and
	 * re-initializes the suspect ones; what was placed, for the pose graph. */
	PlacedLandmarks placeLandmarks(const FrameMeasurements& frame,
		const std::vector<const LandmarkMeasurement*>& firstSightings, const LandmarksToPlace& toReinitialize);
	/** Fuses a heading change into the pending odometry (COdometryAccumulator). */
	void fuseHeadingChange(const HeadingChangeMeasurement& h);
	void moveParticlesTo(const std::vector<se2::Pose>& poses);
	void switchToRelocalizationHypothesis(mrpt::Clock::time_point t);
	void revertLastKidnap();
	void sampleMotionOnly(const MotionPrior& mp);
	/** Explained / plausible weight fractions of every known measurement,
	 * and the spread of the predicted cloud. With the optimal nominal
	 * proposal, each particle's proposal is computed here once (its gate
	 * decisions are the explained test) and returned for the update. */
	void explainedFractions(
		std::vector<KnownMeasurement>& known, const MotionPrior& mp,
		Eigen::Matrix2d& predictedSpreadXY,
		std::vector<PoseGaussianProposal>* optimalProposals) const;
	void normalUpdate(
		const std::vector<KnownMeasurement>& used, const MotionPrior& mp,
		const Eigen::Matrix2d& predictedSpreadXY, double explainedFraction,
		const std::vector<PoseGaussianProposal>* optimalProposals);
	double weighAndUpdateLandmarks(
		CVSlamParticle& p, const se2::Pose& s,
		const std::vector<KnownMeasurement>& used);
	void createLandmark(const LandmarkKey& key, const LandmarkMeasurement& rel,
		mrpt::Clock::time_point t);
	void reinitializeLandmark(
		size_t slot, const LandmarkMeasurement& m, mrpt::Clock::time_point t);
	std::vector<double> normalizedLinearWeights() const;
	/** Weighted mean of the particles' current poses (circular in phi). */
	se2::Pose cloudMean(const std::vector<double>& normalizedWeights) const;
	/** Collapses the cloud onto its mean before the first landmark is
	 * created ([vslam_landmarks] anchor_first_landmark). */
	void anchorMapFrame();
	/** Adds the frame's keyframe, measurements and new landmarks to the
	 * pose graph; on a loop closure, optimizes it and moves the particles
	 * and their maps onto the solution. */
	void updateLoopClosureGraph(
		mrpt::Clock::time_point t, const std::vector<KnownMeasurement>& used,
		const std::vector<std::pair<size_t, LandmarkMeasurement>>& placed);
	void applyLoopClosure(const CLandmarkPoseGraph::Correction& c);
};

}  // namespace vslam

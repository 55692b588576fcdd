#pragma once
/** \file CKidnapDetector.h
 * Kidnap detection (the paper leaves the criterion open; ours is derived
 * in doc/mixture-proposal.md).
 *
 * Evidence. A measurement is "explained" when it falls inside the
 * validation gate of particles holding at least `explained_min_fraction`
 * of the weight, under the predictive distribution (odometry noise
 * included). *Anchored* landmarks count either way: those created no later
 * than the last frame in which an anchored landmark was explained (at
 * start, those of the first frame). Landmarks created since ("young") were
 * placed from the current belief, so their being explained says nothing;
 * not explained, they count against it: while the robot explores, the
 * landmarks made since the last anchored one are often all that a robot
 * carried back there can see.
 *
 * Test. At the first frame with evidence and none of it explained, a
 * relocalization hypothesis starts: dual particles drawn from those
 * measurements with a uniform pose prior (the paper's kidnap mode),
 * carried forward with odometry. Each later frame with such evidence must
 * be explained by the hypothesis, which is then reweighted; otherwise the
 * hypothesis restarts from that frame. Kidnapping is declared when the
 * hypothesis has explained `min_unexplained_frames` frames over at least
 * `min_distinct_landmarks` landmarks, or `single_landmark_frames` frames
 * of one landmark if an anchored landmark that measures the whole pose (a
 * visual landmark) is among its support (a young landmark is placed less
 * surely; a point landmark leaves the pose free on a circle around it),
 * while the filter explained none. False
 * recognitions are mutually inconsistent, so they keep restarting the
 * hypothesis instead of confirming it. Any explained anchored measurement
 * drops the hypothesis.
 *
 * Look-alikes. A hypothesis that explained `min_unexplained_frames` frames
 * and was then dropped by an explained anchored measurement, or a kidnap
 * that was reverted (below), was a consistent story told by the wrong
 * landmarks: one recognized where it is not (a poster hung twice) or placed
 * wrong. Its landmarks are marked as look-alikes for the rest of the run,
 * and a look-alike no longer confirms a kidnap alone (it still counts among
 * `min_distinct_landmarks`).
 *
 * Return. One landmark recognized falsely but consistently (a repeated
 * texture) confirms a hypothesis as well as a real kidnap does. So a
 * declared kidnap stays reversible: the cloud the filter left becomes a
 * return hypothesis, carried forward with odometry. A landmark outside the
 * kidnap's support, anchored before it, decides: explained by the new
 * cloud, the kidnap is confirmed and the return dropped; explained only by
 * the return hypothesis, the filter goes back to it (Verdict::Reverted).
 */
#include <libvslam/filter/CRelocalizationHypothesis.h>
#include <libvslam/filter/KnownMeasurement.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/Clock.h>

#include <cstdint>
#include <optional>
#include <unordered_set>
#include <vector>

namespace vslam
{
class CKidnapDetector
{
   public:
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		bool enabled = true;
		uint32_t min_unexplained_frames = 3;
		uint32_t min_distinct_landmarks = 2;
		/** ... or this many frames when they all measure one visual landmark
		 * (0: never): a carried robot often sees one mapped landmark
		 * briefly, then nothing it knows. */
		uint32_t single_landmark_frames = 4;
		double explained_min_fraction = 0.01;
		/** Keep the cloud left at a kidnap, and go back to it when another
		 * landmark contradicts the kidnap (see the file comment). */
		bool revert_on_contradiction = true;

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& cfg,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& cfg,
			const std::string& section) const override;
	};

	/** One measurement of a known landmark in the current frame. */
	struct Evidence
	{
		KnownMeasurement measurement;
		mrpt::Clock::time_point created{};
		bool explained = false;
	};

	/** What the test needs from the filter for one frame. */
	struct Context
	{
		const MotionPrior& motion;  //!< odometry since the previous frame
		const LandmarkBank& bank;  //!< the best particle's map
		size_t particles;  //!< size of a hypothesis
		const CRobustLikelihood& likelihood;
		mrpt::random::CRandomGenerator& rng;
	};

	enum class Verdict : uint8_t
	{
		Neutral,  //!< no anchored evidence in this frame
		Localized,  //!< an anchored measurement was explained
		Unexplained,  //!< anchored evidence, none explained
		Kidnapped,  //!< the hypothesis is confirmed: switch to it
		/** Another landmark contradicts the last kidnap: switch back to
		 * returnHypothesis(). */
		Reverted
	};

	CKidnapDetector() = default;
	explicit CKidnapDetector(const TOptions& o) : options(o) {}
	TOptions options;

	/** Feeds one frame; call it for every frame, even without evidence. */
	Verdict update(
		mrpt::Clock::time_point t, const std::vector<Evidence>& evidence,
		const Context& ctx);

	/** Whether a landmark created at `created` counts as evidence whether
	 * or not it is explained (a young one counts only when unexplained). */
	bool anchored(mrpt::Clock::time_point created) const
	{
		return m_verified && created <= *m_verified;
	}
	/** True unless the latest anchored evidence was unexplained. */
	bool localized() const { return m_localized; }
	uint64_t kidnapsDetected() const { return m_detections; }
	uint64_t kidnapsReverted() const { return m_reverts; }
	/** Landmarks marked as look-alikes (see the file comment). */
	size_t lookAlikes() const { return m_lookAlikes.size(); }
	const CRelocalizationHypothesis& hypothesis() const { return m_hypothesis; }
	/** The filter switched to the hypothesis: drops it, and keeps the cloud
	 * it left (poses, log-weights, map) as the return hypothesis. */
	void acceptHypothesis(
		const std::vector<se2::Pose>& left, const std::vector<double>& leftLogW,
		const LandmarkBank& leftBank);
	const CRelocalizationHypothesis& returnHypothesis() const { return m_return; }
	/** Drops the return hypothesis (after the filter switched back to it). */
	void clearReturnHypothesis() { m_return.clear(); }

   private:
	std::optional<mrpt::Clock::time_point> m_verified;
	bool m_localized = true;
	uint64_t m_detections = 0;
	CRelocalizationHypothesis m_hypothesis;
	bool m_hypothesisConfirmableAlone = false;  //!< a landmark that confirmsAlone() supports it
	CRelocalizationHypothesis m_return;
	/** What the return test may use: landmarks anchored when the kidnap was
	 * declared, other than those that confirmed it. */
	mrpt::Clock::time_point m_returnAnchor{};
	std::unordered_set<LandmarkKey, LandmarkKeyHash> m_kidnapSupport;
	uint64_t m_reverts = 0;
	std::unordered_set<LandmarkKey, LandmarkKeyHash> m_lookAlikes;

	/** Whether this evidence may confirm a kidnap as the only landmark. */
	bool confirmsAlone(const Evidence& e) const;
	/** The hypothesis is dropped by an explained anchored measurement: if it
	 * had explained enough frames, its landmarks become look-alikes. */
	void dropHypothesis();
	/** The return test on one frame's evidence; true if it reverts. */
	bool contradictsKidnap(const std::vector<Evidence>& evidence, const Context& ctx);
};

}  // namespace vslam

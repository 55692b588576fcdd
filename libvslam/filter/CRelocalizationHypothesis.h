#pragma once
/** \file CRelocalizationHypothesis.h
 * The alternative "the robot is somewhere else" that kidnap detection
 * tests: dual particles drawn from measurements the filter cannot explain,
 * with a uniform pose prior (the paper's kidnap-mode particles), carried
 * forward with odometry and weighted by later measurements. It reads the
 * map of the filter's best particle at the time it starts (an O(1) copy of
 * the persistent bank) and never writes it.
 */
#include <libvslam/filter/CVSlamParticle.h>
#include <libvslam/filter/KnownMeasurement.h>
#include <libvslam/filter/MotionPrior.h>
#include <libvslam/models/CRobustLikelihood.h>
#include <libvslam/models/DualProposal.h>

#include <cstdint>
#include <unordered_set>
#include <vector>

namespace mrpt::random
{
class CRandomGenerator;
}

namespace vslam
{
class CRelocalizationHypothesis
{
   public:
	bool active() const { return !m_poses.empty(); }
	void clear();

	/** Starts from measurements no particle explains: n dual samples
	 * (uniform heading prior) from the most informative one, weighted by all the
	 * measurements under a uniform pose prior, then resampled. Returns false
	 * if no usable dual proposal exists. */
	bool start(
		const std::vector<KnownMeasurement>& ms, const LandmarkBank& bank,
		size_t n, const CRobustLikelihood& likelihood,
		mrpt::random::CRandomGenerator& rng);

	/** Starts from a cloud the filter held (poses with log-weights, and
	 * their map): resampled to equal weights. */
	void startFrom(
		const std::vector<se2::Pose>& poses, const std::vector<double>& logW,
		const LandmarkBank& bank);

	/** Moves every particle by the odometry since the last call. */
	void predict(const MotionPrior& motion, mrpt::random::CRandomGenerator& rng);

	/** Weight fraction of particles whose validation gate holds the
	 * best-explained of the measurements. */
	double explainedFraction(
		const std::vector<KnownMeasurement>& ms,
		const CRobustLikelihood& likelihood) const;

	/** Weighs the particles by the measurements and resamples: the
	 * hypothesis survived one more test. */
	void confirm(
		const std::vector<KnownMeasurement>& ms,
		const CRobustLikelihood& likelihood, mrpt::random::CRandomGenerator& rng);

	/** Frames it has explained, counting the one it started from. */
	size_t support() const { return m_support; }
	size_t distinctLandmarks() const { return m_landmarks.size(); }
	const std::unordered_set<LandmarkKey, LandmarkKeyHash>& landmarks() const
	{
		return m_landmarks;
	}
	const std::vector<se2::Pose>& poses() const { return m_poses; }
	const LandmarkBank& bank() const { return m_bank; }

   private:
	std::vector<se2::Pose> m_poses;
	LandmarkBank m_bank;
	size_t m_support = 0;
	std::unordered_set<LandmarkKey, LandmarkKeyHash> m_landmarks;

	double logLikelihood(
		const se2::Pose& s, const std::vector<KnownMeasurement>& ms,
		const CRobustLikelihood& likelihood) const;
	void resample(const std::vector<double>& logW);
};

/** Index of the measurement whose dual proposal is most informative: pose
 * measurements first, then the closest range-bearing one. */
size_t mostInformativeMeasurement(const std::vector<KnownMeasurement>& ms);

}  // namespace vslam

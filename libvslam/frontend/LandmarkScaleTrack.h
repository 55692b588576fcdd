#pragma once
/** \file LandmarkScaleTrack.h
 * A landmark's scale, refined from its later sightings.
 *
 * A landmark's 3-D points get their scale from the odometry over its short
 * creation baseline (a few tenths of a metre), so a landmark comes out a
 * few percent too large or too small, and every later measurement of it is
 * off by that share of its range. Each recognition measures where the robot
 * is in the landmark frame, in the landmark's own units; between two
 * recognitions of the same landmark the odometry measures the same
 * displacement in metres. Their ratio, over every such pair, estimates the
 * landmark's scale error k (landmark length / true length):
 *
 *     v_i = k * o_i + noise,   var = 2 sigma_v^2 + k^2 sigma_T^2 * travel_i
 *
 * with v_i the displacement from the two pose solves (landmark units), o_i
 * the odometry displacement rotated into the landmark frame (by the heading
 * of the first solve), sigma_v the solves' predicted position std and
 * sigma_T the odometry's translation noise per sqrt(metre) travelled (the
 * motion model's). The creation baseline B enters as a prior k = 1 with
 * variance sigma_T^2 / B. The estimate is
 *
 *     k = (B / sigma_T^2 + sum <v_i, o_i> / var_i) / (B / sigma_T^2 + sum d_i / var_i),
 *     d_i = |o_i|^2 - 2 sigma_T^2 travel_i
 *
 * The odometry's noise lengthens its displacements on average (|o_i|^2 by
 * 2 sigma_T^2 travel_i, both axes), so a plain least-squares ratio (|o_i|^2
 * for d_i) would take every landmark for smaller than it is, by about 1.7%
 * for pairs 0.3 m long; d_i is the unbiased estimate of the true squared
 * displacement (an errors-in-variables correction; it relies on sigma_T
 * being the odometry's true noise, which [vslam_scale_refinement]
 * odometry_sigma can state).
 *
 * Pairs are chained (each sighting is the next pair's start) so their
 * odometry noise is independent; a pair is formed once the robot has
 * travelled pairMinTravel (short pairs measure little), and not over more
 * than pairMaxTravel (odometry drift).
 *
 * A wrong or poor recognition at either end makes a wrong pair. Every pair
 * is judged again whenever one is added, against the estimate from the
 * prior and the other pairs in it (leave one out): the worst beyond the 99%
 * gate of its variance (with that of the estimate) is left out and the rest
 * judged again, until none is. So a wrong pair that the uncertain prior
 * alone could not tell apart (the first, often the longest) is dropped as
 * soon as later pairs disagree with it, and a pair left out comes back
 * when the estimate moves towards it. The most recent kJudgedPairs pairs
 * are kept for this; older ones are folded into the prior as they were
 * last judged, so a landmark's memory stays bounded.
 */
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/math/TPoint2D.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace vslam
{
struct TScaleTrackOptions
{
	double odometrySigma = 0.05;  //!< m / sqrt(m) travelled
	double pairMinTravel = 0.3;  //!< m
	double pairMaxTravel = 2.0;  //!< m
};

/** One recognition, as the scale track needs it. Positions are the
 * camera's (the landmark's units apply to it; the mount's offset on the
 * robot is in metres), headings the robot's. */
struct ScaleSighting
{
	/** From the pose solve, in the landmark's current units. */
	mrpt::math::TPoint2D cameraInLandmark;
	double headingInLandmark = 0;  //!< rad
	double stdPosition = 0;  //!< the pose solve's predicted position std, current units
	/** From odometry (the robot's odometry pose composed with the mount). */
	mrpt::math::TPoint2D cameraInOdometry;
	double headingInOdometry = 0;  //!< rad
	double travelled = 0;  //!< odometry path length so far, m
};

class CLandmarkScaleTrack
{
   public:
	/** INI section [vslam_scale_refinement]. */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		static constexpr const char* kSection = "vslam_scale_refinement";

		/** Refine each landmark's scale from its later sightings against the
		 * odometry between them. */
		bool enabled = true;
		/** The odometry's translation noise, m/sqrt(m) travelled; 0: the
		 * motion model's sigma_T ([vslam_motion_model] of the same INI), so
		 * the two cannot disagree by oversight. The track takes this noise's
		 * mean share out of each odometry displacement, so it should be the
		 * odometry's true noise: one stated too large makes landmarks too
		 * small. */
		double odometry_sigma = 0;

		/** Sets odometry_sigma to the motion model's sigma_T if it is 0. */
		void takeOdometryNoiseFrom(double motionModelSigmaT);
		/** The track's settings; an odometry_sigma still 0 (options not read
		 * from an INI) is the motion model's default. */
		TScaleTrackOptions settings() const;

		void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
		void saveToConfigFile(mrpt::config::CConfigFileBase& target, const std::string& section) const override;
	};

	CLandmarkScaleTrack() = default;
	/** Starts the track of a landmark built over `creationBaseline` metres
	 * of odometry. */
	CLandmarkScaleTrack(double creationBaseline, const TScaleTrackOptions& settings);

	/** Adds a sighting. Returns the factor by which the landmark's lengths
	 * (its points, and the translation of this sighting's measurement)
	 * must be multiplied to bring them to the new estimate (1: unchanged). */
	double addSighting(const ScaleSighting& sighting);

	/** The estimated scale error k of the landmark as built (its lengths
	 * over the true ones), and its standard deviation. */
	double scaleError() const { return m_weightedSum / m_information; }
	double scaleErrorStd() const;
	/** The factor the landmark's lengths carry now, relative to creation. */
	double appliedFactor() const { return 1 / scaleError(); }
	/** Pairs in the estimate, and pairs left out of it (as last judged). */
	int pairsUsed() const { return m_used; }
	int pairsRejected() const { return m_rejected; }
	/** What a saved map keeps of a track: the estimate, with every pair
	 * folded in as last judged. */
	struct TState
	{
		double information = 1, weightedSum = 1;
		int pairsUsed = 0, pairsRejected = 0;
	};
	TState state() const { return {m_information, m_weightedSum, m_used, m_rejected}; }
	/** The track of a landmark loaded from a map: its estimate is the
	 * prior, and pairs start with its next sighting (a new run's odometry
	 * does not continue the old one's). Throws std::invalid_argument if the
	 * state is not positive and finite. */
	static CLandmarkScaleTrack resumed(const TState& state, const TScaleTrackOptions& settings);

	/** Heap memory held (the pairs kept for judging). */
	size_t bytes() const { return m_pairs.capacity() * sizeof(Pair); }

	/** Pairs judged again whenever one is added. */
	static constexpr size_t kJudgedPairs = 16;

   private:
	/** A pair as the estimate needs it: v and o (landmark units as built,
	 * metres) by their products, and the variance's parts. */
	struct Pair
	{
		double vv = 0, vo = 0, oo = 0;  //!< <v, v>, <v, o>, <o, o>
		double sightingsVariance = 0;  //!< 2 sigma_v^2 (both ends)
		double travel = 0;  //!< m
		bool used = false;  //!< in the estimate, as last judged
		double variance(double k, double odometrySigma) const
		{
			return sightingsVariance + k * k * odometrySigma * odometrySigma * travel;
		}
		/** |o|^2 less the odometry noise's mean share of it: the true
		 * squared displacement, unbiased (may come out negative). */
		double displacementSquared(double odometrySigma) const
		{
			return oo - 2 * odometrySigma * odometrySigma * travel;
		}
	};
	/** The oldest pair leaves the judged window, into the fixed part if it
	 * was in the estimate. */
	void foldOldestPair();
	/** Judges every kept pair again (worst first) and sets the estimate.
	 * The pairs' variances take k as it was before. */
	void estimate();

	TScaleTrackOptions m_settings;
	/** The previous sighting, positions in the units as built. */
	std::optional<ScaleSighting> m_anchor;
	/** The prior k = 1 and the pairs folded into it. */
	double m_fixedInformation = 1, m_fixedWeightedSum = 1;
	std::vector<Pair> m_pairs;  //!< the most recent, oldest first
	double m_information = 1, m_weightedSum = 1;  //!< the estimate: fixed part and used pairs
	int m_used = 0, m_rejected = 0;  //!< of the pairs kept and folded
	int m_foldedUsed = 0, m_foldedRejected = 0;
};
}  // namespace vslam

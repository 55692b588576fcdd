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
 * variance sigma_T^2 / B. The weighted least-squares estimate is
 *
 *     k = (B / sigma_T^2 + sum <v_i, o_i> / var_i) / (B / sigma_T^2 + sum |o_i|^2 / var_i)
 *
 * Pairs are chained (each sighting is the next pair's start) so their
 * odometry noise is independent; a pair is formed once the robot has
 * travelled scale_pair_min_travel (short pairs measure little), and not
 * over more than scale_pair_max_travel (odometry drift). A pair whose
 * residual is beyond the 99% gate of its variance (with that of k; a wrong recognition at
 * either end) is left out and the chain restarts at the newer sighting.
 */
#include <mrpt/math/TPoint2D.h>

#include <optional>

namespace vslam
{
struct TScaleRefinementSettings
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

class LandmarkScaleTrack
{
   public:
	LandmarkScaleTrack() = default;
	/** Starts the track of a landmark built over `creationBaseline` metres
	 * of odometry. */
	LandmarkScaleTrack(double creationBaseline, const TScaleRefinementSettings& settings);

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
	int pairsUsed() const { return m_used; }
	int pairsRejected() const { return m_rejected; }

   private:
	TScaleRefinementSettings m_settings;
	/** The previous sighting, positions in the units as built. */
	std::optional<ScaleSighting> m_anchor;
	double m_information = 1, m_weightedSum = 1;  //!< the prior k = 1
	int m_used = 0, m_rejected = 0;
};
}  // namespace vslam

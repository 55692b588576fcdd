#pragma once
/** \file CMeasurementExtractor.h
 * Turns the observations of one sensory frame into filter input: visual
 * measurements (through the pre-filter, with noise Sigma_vis), landmark
 * creation events, and range-bearing measurements of point landmarks
 * (MRPT's CObservationBearingRange with landmark IDs). Counts what it
 * rejects and why.
 */
#include <libvslam/filter/CPreFilter.h>
#include <libvslam/models/LandmarkTypes.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/Clock.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace vslam
{
/** A landmark-created event: the new landmark's frame relative to the
 * robot (z, pose kind) with its uncertainty (R). */
struct LandmarkCreation
{
	LandmarkKey key;
	LandmarkMeasurement relative;
};

/** Everything one frame (one image / one sensory frame) says. */
struct FrameMeasurements
{
	mrpt::Clock::time_point timestamp{};
	std::vector<LandmarkMeasurement> measurements;
	std::vector<LandmarkCreation> creations;
	bool empty() const { return measurements.empty() && creations.empty(); }
};

/** Counts of what the extractor saw, accepted and rejected. */
struct TExtractionStats
{
	uint64_t visualSeen = 0, visualAccepted = 0;
	uint64_t rejectedProjErrRMS = 0, rejectedNPoints = 0, rejectedSlope = 0, rejectedHeight = 0;
	/** Accepted, but above evidence_max_Slope: no kidnap evidence. */
	uint64_t visualNoKidnapEvidence = 0;
	uint64_t creationsSeen = 0;
	uint64_t rangeBearingSeen = 0, rangeBearingAccepted = 0;
	uint64_t rejectedNoLandmarkID = 0, rejectedRangeLimits = 0;
};

class CMeasurementExtractor
{
   public:
	/** Visual measurement noise Sigma_vis (paper: diag(81 cm^2, 81 cm^2,
	 * 0.0019 rad^2)). */
	struct TVisualOptions : public mrpt::config::CLoadableOptions
	{
		double std_dx = 0.09;  //!< m
		double std_dy = 0.09;  //!< m
		double std_dphi = std::sqrt(0.0019);  //!< rad (INI: degrees)
		/** Timestamp uncertainty of the images against odometry (s). */
		double time_jitter_std = 0;
		/** Each measurement's noise is Sigma_vis plus this factor squared
		 * times the covariance its pose solve predicts (relPoseCov, where
		 * the rawlog has one): a measurement from a few points in a small
		 * part of the image counts for less. The prediction sees only the
		 * pixel error, not the landmark's own, hence a factor. 0: Sigma_vis
		 * alone (the paper). */
		double predicted_cov_scale = 0;

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& cfg,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& cfg,
			const std::string& section) const override;
	};

	/** Range-bearing measurement options. */
	struct TRangeBearingOptions : public mrpt::config::CLoadableOptions
	{
		/** Noise; 0 takes sensor_std_range / sensor_std_yaw from each
		 * observation. */
		double std_range = 0;  //!< m
		double std_bearing = 0;  //!< rad (INI: degrees)
		double min_range = 0;  //!< m
		double max_range = 0;  //!< m, 0: no limit
		/** Timestamp uncertainty of the measurements against odometry (s). */
		double time_jitter_std = 0;

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& cfg,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& cfg,
			const std::string& section) const override;
	};

	TVisualOptions visual;
	TRangeBearingOptions rangeBearing;
	CPreFilter preFilter;

	/** Extracts the frame; throws InputError on non-finite values or a
	 * range-bearing observation without any noise figure. */
	FrameMeasurements extract(const mrpt::obs::CSensoryFrame& sf);

	const TExtractionStats& stats() const { return m_stats; }

   private:
	TExtractionStats m_stats;
};

}  // namespace vslam

#pragma once
/** \file CMeasurementExtractor.h
 * Turns the observations of one sensory frame into filter input: visual
 * measurements (through the pre-filter, with noise Sigma_vis), landmark
 * creation events, and range-bearing measurements of point landmarks
 * (MRPT's CObservationBearingRange with landmark IDs), and the front-end's
 * heading changes between images (fused into the odometry by the filter).
 * Counts what it rejects and why.
 */
#include <libvslam/filter/CPreFilter.h>
#include <libvslam/models/LandmarkTypes.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/Clock.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace mrpt::obs
{
class CObservationBearingRange;
}

namespace vslam
{
class CObservationVisualLandmark;
class CObservationLandmarkCreated;
class CObservationHeadingChange;

/** A landmark-created event: the new landmark's frame relative to the
 * robot (z, pose kind) with its uncertainty (R). */
struct LandmarkCreation
{
	LandmarkKey key;
	LandmarkMeasurement relative;
};

/** The robot's heading change from one image (`from`) to the next (`to`),
 * with the variance the filter gives it. */
struct HeadingChangeMeasurement
{
	mrpt::Clock::time_point from{}, to{};
	double dphi = 0;  //!< rad
	double variance = 0;  //!< rad^2
};

/** Everything one frame (one image / one sensory frame) says. */
struct FrameMeasurements
{
	mrpt::Clock::time_point timestamp{};
	std::vector<LandmarkMeasurement> measurements;
	std::vector<LandmarkCreation> creations;
	/** Corrects the odometry; not a measurement of the map. */
	std::optional<HeadingChangeMeasurement> headingChange;
	/** No landmark measurement or creation (a heading change may be there). */
	bool empty() const { return measurements.empty() && creations.empty(); }
};

/** Counts of what the extractor saw, accepted and rejected. */
struct TExtractionStats
{
	uint64_t visualSeen = 0, visualAccepted = 0;
	uint64_t rejectedProjErrRMS = 0, rejectedNPoints = 0, rejectedSlope = 0;
	uint64_t creationsSeen = 0;
	uint64_t rangeBearingSeen = 0, rangeBearingAccepted = 0;
	uint64_t rejectedNoLandmarkID = 0, rejectedRangeLimits = 0;
	/** Heading changes seen, and passed on ([vslam_heading_change] enabled;
	 * one per frame: with several cameras, the most precise). */
	uint64_t headingChangesSeen = 0, headingChangesPassed = 0;
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
		/** Each measurement's noise is Sigma_vis plus this factor squared
		 * times the covariance its pose solve predicts (relPoseCov, where
		 * the rawlog has one): a measurement from a few points in a small
		 * part of the image counts for less. The prediction sees only the
		 * pixel error, not the landmark's own, hence a factor: 4 is about how
		 * far the actual errors exceed the prediction. 0: Sigma_vis alone
		 * (the paper). */
		double predicted_cov_scale = 4;

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

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& cfg,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& cfg,
			const std::string& section) const override;
	};

	/** [vslam_heading_change]: the front-end's heading change between two
	 * images (CObservationHeadingChange) fused into the odometry between
	 * them (COdometryAccumulator.h). Not in the paper. */
	struct THeadingChangeOptions : public mrpt::config::CLoadableOptions
	{
		bool enabled = true;
		/** The variance given to a heading change is its predicted variance
		 * plus kMinStd^2, a floor against a zero variance from a perfect fit. */
		static constexpr double kMinStd = 0.01 * M_PI / 180;  //!< rad
		/** A heading change beyond this chi-square gate of the odometry
		 * (1 degree of freedom) is not used. */
		double gate_probability = 0.999;

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& cfg,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& cfg,
			const std::string& section) const override;
	};

	TVisualOptions visual;
	TRangeBearingOptions rangeBearing;
	THeadingChangeOptions headingChange;
	CPreFilter preFilter;

	/** Extracts the frame; throws InputError on non-finite values or a
	 * range-bearing observation without any noise figure. */
	FrameMeasurements extract(const mrpt::obs::CSensoryFrame& sf);

	const TExtractionStats& stats() const { return m_stats; }

   private:
	void addVisual(const CObservationVisualLandmark& v, FrameMeasurements& out);
	void addCreation(const CObservationLandmarkCreated& c, FrameMeasurements& out);
	/** The frame keeps its most certain heading change. */
	void addHeadingChange(const CObservationHeadingChange& h, FrameMeasurements& out);
	void addRangeBearing(const mrpt::obs::CObservationBearingRange& br, FrameMeasurements& out);

	TExtractionStats m_stats;
};

}  // namespace vslam

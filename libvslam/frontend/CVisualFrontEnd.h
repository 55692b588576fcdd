#pragma once
/** \file CVisualFrontEnd.h
 * The visual front-end: camera images in, the paper's observations out.
 * For each image: SIFT features (with the image's own calibration), the
 * landmark database proposes candidates, each is checked by a robust pose
 * solve and becomes a CObservationVisualLandmark; when nothing is
 * recognized the image joins the views for a new landmark, which is built
 * once enough views with enough baseline (from odometry) are at hand and
 * announced as a CObservationLandmarkCreated. The map is bounded by a cap
 * and by pruning landmarks that are expected but repeatedly not seen.
 * Optionally ([vslam_heading_measurement]), each image is also matched with
 * the same camera's previous one for the robot's heading change in between
 * (CObservationHeadingChange, HeadingChange.h).
 * Each component owns its options and INI section; TOptions composes them
 * and is the one place where they share a value (the features' ratio test).
 */
#include <libvslam/config/KeyValidation.h>
#include <libvslam/config/Overrides.h>
#include <libvslam/frontend/CLandmarkDatabase.h>
#include <libvslam/frontend/HeadingChange.h>
#include <libvslam/frontend/ImageFeatures.h>
#include <libvslam/frontend/LandmarkCreator.h>
#include <libvslam/frontend/LandmarkRecognizer.h>
#include <libvslam/frontend/LandmarkScaleTrack.h>
#include <libvslam/frontend/PinholeCamera.h>
#include <libvslam/obs/CObservationHeadingChange.h>
#include <libvslam/obs/CObservationLandmarkCreated.h>
#include <libvslam/obs/CObservationVisualLandmark.h>
#include <libvslam/obs/CVSlamMap.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/poses/CPose2D.h>

#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vslam
{
class CVisualFrontEnd
{
   public:
	/** The options of every front-end component, each read from its own
	 * INI section. */
	struct TOptions
	{
		CFeatureExtractor::TOptions features;
		CImageCalibration::TOptions camera;
		CLandmarkCreator::TOptions creation;
		CLandmarkScaleTrack::TOptions scale;
		CLandmarkRecognizer::TOptions recognition;
		CLandmarkDatabase::TOptions database;
		CHeadingChangeEstimator::TOptions heading;

		/** Reads every section (absent keys keep their defaults). */
		void loadFromConfig(const mrpt::config::CConfigFileBase& cfg);
		/** Writes every section with comments. */
		void saveToConfig(mrpt::config::CConfigFileBase& cfg) const;
		/** Adds every section's keys to `known`, and where the keys of the
		 * former single [vslam_frontend] section went. */
		void registerKnownKeys(config::KnownKeys& known) const;
		/** Scale refinement's odometry noise from the motion model where unset. */
		void takeOdometryNoiseFrom(double motionModelSigmaT) { scale.takeOdometryNoiseFrom(motionModelSigmaT); }

		// The components, wired to the options they share.
		CLandmarkCreator creator() const
		{
			return CLandmarkCreator(creation, features.match_ratio, recognition.structure_weighted);
		}
		CLandmarkRecognizer recognizer() const { return CLandmarkRecognizer(recognition, features.match_ratio); }
		CHeadingChangeEstimator headingEstimator() const
		{
			return CHeadingChangeEstimator(heading, features.match_ratio);
		}
	};

	explicit CVisualFrontEnd(const TOptions& options);

	struct StageSeconds
	{
		double features = 0, search = 0, pose = 0, creation = 0, heading = 0;
		double total() const { return features + search + pose + creation + heading; }
	};
	struct Output
	{
		std::vector<CObservationVisualLandmark::Ptr> measurements;
		std::vector<CObservationLandmarkCreated::Ptr> created;
		/** At most one: from this image's camera's previous image. */
		std::vector<CObservationHeadingChange::Ptr> headingChanges;
		std::vector<int64_t> pruned;  //!< landmarks removed by map bounding
		StageSeconds seconds;
		size_t features = 0;
	};

	/** Processes one image taken at `odometryPose` (the robot's pose from
	 * accumulated odometry). `what` names the image in errors. Throws
	 * std::invalid_argument on an unusable calibration and std::runtime_error
	 * if the image cannot be loaded. */
	Output process(
		const mrpt::obs::CObservationImage& image, const mrpt::poses::CPose2D& odometryPose,
		const std::string& what);

	/** Loads a saved map's visual landmarks, before the first image.
	 * `worldInOdometry` places the map's frame in this run's odometry
	 * frame (the inverse of the start pose), so each landmark is expected
	 * in view where the map has it. New landmarks take IDs after the map's.
	 * Throws std::invalid_argument if the map's descriptors cannot be used
	 * with this configuration's descriptor storage. */
	void loadMap(const CVSlamMap& map, const mrpt::poses::CPose2D& worldInOdometry);
	/** Localization only: no landmark is created, pruned or rescaled. */
	void fixMap() { m_mapFixed = true; }
	/** Adds every landmark's appearance, the descriptor storage, the next
	 * landmark ID and the first image's calibration to `map`. */
	void saveMap(CVSlamMap& map) const;

	const CLandmarkDatabase& database() const { return m_database; }
	/** Totals over all images so far. */
	const StageSeconds& totalSeconds() const { return m_total; }
	size_t imagesProcessed() const { return m_images; }
	/** Recognitions dropped for a degenerate pose solve (no uncertainty). */
	size_t poorlyConditionedRecognitions() const { return m_poorlyConditioned; }
	/** Recognitions not reported because the odometry since the landmark's
	 * last one does not put it there ([vslam_recognition] odometry_gate_s). */
	size_t inconsistentRecognitions() const { return m_inconsistent; }
	/** Landmark creations tried, and those rejected by reason (the
	 * creator's reason with its numbers replaced by "N"). */
	size_t creationAttempts() const { return m_creationAttempts; }
	const std::map<std::string, size_t>& creationRejections() const { return m_creationRejections; }
	/** Heading changes measured, and image pairs where none fit. */
	size_t headingChangesMeasured() const { return m_headingChangesMeasured; }
	size_t headingChangesFailed() const { return m_headingChangesFailed; }

   private:
	/** This image's features (encoded for the database) and camera pose;
	 * with the heading measurement, also the heading change from the previous image. */
	CreationView viewOf(const mrpt::obs::CObservationImage& obs, const mrpt::poses::CPose2D& odometryPose,
		const std::string& what, Output& out);
	/** The landmarks recognized in the image (IDs); the recognitions fit to
	 * report are added to out.measurements. */
	struct Recognitions
	{
		std::vector<int64_t> ids;
	};
	Recognitions recognize(const CreationView& view, const mrpt::obs::CObservationImage& obs,
		const mrpt::poses::CPose2D& odometryPose, Output& out);
	/** Whether a recognition is reported; counts the reason when it is not. */
	bool reportable(const VisualLandmarkModel& landmark, const VisualMeasurement& m, double time,
		const mrpt::poses::CPose2D& odometryPose);
	/** Keeps the view for creation when no landmark is recognized,
	 * and builds a landmark once there are enough views along the motion. */
	void collectForCreation(CreationView view, const Recognitions& recognized, const mrpt::obs::CObservationImage& obs,
		const mrpt::poses::CPose2D& odometryPose, Output& out);
	/** A landmark from the newest views; on success it goes
	 * to the database and out.created, else the oldest view is dropped. */
	void createFromViews(const mrpt::obs::CObservationImage& obs, const mrpt::poses::CPose2D& odometryPose, Output& out);
	/** Refines the scale of the landmark just recognized in `m` from this
	 * sighting; rescales its points and `m` when the estimate moves. */
	void refineScale(VisualLandmarkModel& landmark, VisualMeasurement& m, const mrpt::poses::CPose2D& odometryPose,
		const mrpt::poses::CPose3D& mount);
	void prune(const mrpt::poses::CPose2D& odometryPose, const std::vector<int64_t>& recognized, Output& out);
	/** The heading change from the camera's previous image to this one, if
	 * one fits; this image becomes the camera's previous one. */
	void measureHeadingChange(const mrpt::obs::CObservationImage& obs,
		const ImageFeatures& features, const mrpt::poses::CPose2D& odometryPose, Output& out);

	/** The last image of a camera, for the next heading change. */
	struct PreviousImage
	{
		ImageFeatures features;
		mrpt::poses::CPose2D odometryPose;
		mrpt::Clock::time_point timestamp;
	};

	TOptions m_options;
	CFeatureExtractor m_extractor;
	CLandmarkDatabase m_database;
	CLandmarkCreator m_creator;
	CLandmarkRecognizer m_recognizer;
	CHeadingChangeEstimator m_headingEstimator;
	/** Recent unrecognized views for landmark creation, oldest first, with
	 * the odometry pose each was taken at. */
	std::deque<std::pair<CreationView, mrpt::poses::CPose2D>> m_views;
	int64_t m_nextId = 1;
	bool m_mapFixed = false;
	std::optional<mrpt::img::TCamera> m_camera;  //!< the first image's calibration
	double m_travelled = 0;  //!< odometry path length so far, m
	std::optional<mrpt::poses::CPose2D> m_lastOdometry;
	StageSeconds m_total;
	size_t m_images = 0;
	size_t m_poorlyConditioned = 0;
	size_t m_inconsistent = 0;
	size_t m_creationAttempts = 0;
	std::map<std::string, size_t> m_creationRejections;
	std::map<std::string, PreviousImage> m_previousImage;  //!< by sensor label
	size_t m_headingChangesMeasured = 0, m_headingChangesFailed = 0;
};

/** The front-end options of an INI file ("" for none) with `--set`
 * overrides, strictly (unknown keys and bad values are ConfigError naming
 * the file), with the odometry noise of its [vslam_motion_model] where
 * scale refinement's is 0. Used by the apps that run the front-end alone. */
CVisualFrontEnd::TOptions loadFrontEndOptions(
	const std::string& iniFile, const std::vector<config::Override>& overrides);
}  // namespace vslam

#pragma once
/** \file PosedImageEvaluation.h
 * The front-end on real photographs with exact camera poses (Strecha
 * layout): for every run of consecutive views, build a landmark with the
 * true baseline plus odometry-like noise standing in for odometry, try to
 * recognize it from every other view, and compare each measurement with
 * the ground-truth relative pose.
 *
 * Each camera stands for a robot: the world is turned so that z is up
 * (the data's z points down), the robot sits at the camera centre with its
 * heading along the optical axis projected on the floor. The camera mount is
 * "calibrated" as the mean over the views of the camera's orientation in
 * that robot frame (the photographs share a common upward tilt); each
 * view's own deviation from it is left for the front-end to cope with.
 */
#include <libvslam/frontend/CVisualFrontEnd.h>
#include <libvslam/io/StrechaDataset.h>
#include <libvslam/models/SE2.h>
#include <mrpt/poses/CPose3D.h>

#include <cstdint>
#include <string>
#include <vector>

namespace vslam
{
struct TPosedImageEvaluationOptions
{
	uint32_t seed = 1;
	/** Odometry-like noise on each increment between creation views:
	 * relative translation error (std) and heading error (std, deg). */
	double odometryTranslationNoise = 0.02;
	double odometryHeadingNoiseDeg = 1.0;
};

struct RecognitionRecord
{
	int landmarkView = 0;  //!< newest view of the landmark (its frame)
	int queryView = 0;
	bool recognized = false;
	double distance = 0;  //!< true distance query robot -> landmark frame
	double viewpointChangeDeg = 0;  //!< heading difference of the two views
	double headingErrorDeg = 0, translationError = 0;  //!< when recognized
	int NPoints = 0;
	double ProjErrRMS = 0, Slope = 0;
};

struct PosedImageEvaluation
{
	int landmarksTried = 0, landmarksCreated = 0;
	std::vector<RecognitionRecord> records;
	double featureSeconds = 0, creationSeconds = 0, recognitionSeconds = 0;
	mrpt::poses::CPose3D mount;  //!< the calibrated camera mount used
	/** Per landmark built: its oldest view's refined pose against the truth. */
	std::vector<double> creationRotationErrorDeg, creationDirectionErrorDeg, creationScaleError;
	std::vector<double> landmarkBytes;  //!< per landmark built, as stored
};

/** The planar robot pose a camera stands for (see the file comment). */
se2::Pose robotPoseOfCamera(const StrechaView& view);

PosedImageEvaluation evaluatePosedImages(
	const std::vector<StrechaView>& views, const CVisualFrontEnd::TOptions& frontEnd,
	const TPosedImageEvaluationOptions& options);

/** Markdown tables: accuracy (medians), recognition share by viewpoint change. */
std::string formatPosedImageEvaluation(const std::string& title, const PosedImageEvaluation& e);
}  // namespace vslam

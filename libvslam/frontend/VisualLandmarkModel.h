#pragma once
/** \file VisualLandmarkModel.h
 * What the front-end keeps of a landmark: its ID, its 3-D points in the
 * landmark frame (the robot pose at creation: x forward, y left, z up),
 * their descriptors and bookkeeping. Not the images.
 */
#include <libvslam/frontend/LandmarkScaleTrack.h>
#include <libvslam/frontend/OdometryConsistency.h>
#include <mrpt/poses/CPose2D.h>
#include <opencv2/core.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace vslam
{
struct VisualLandmarkModel
{
	int64_t id = 0;
	std::vector<cv::Point3f> points;  //!< landmark frame, metres
	/** Per point: its std along the ray from the camera that built the
	 * landmark, relative to its distance (StructureUncertainty.h); kept
	 * only with recognition_structure_weighted, empty otherwise (the
	 * points are then taken as exact). */
	std::vector<float> depthStd;
	/** One row per point: CV_32F (128 floats), or CV_8U when compact. */
	cv::Mat descriptors;
	double createdAt = 0;  //!< s
	/** The robot's odometry pose when it was built (for "expected in view"). */
	mrpt::poses::CPose2D createdAtOdometry;
	int views = 0;  //!< images it was built from
	double reprojectionRms = 0;  //!< px, after refinement at creation
	int recognitions = 0;
	int missesInARow = 0;
	double lastSeen = 0;  //!< s
	/** Its last reported recognition (recognition_odometry_gate_s). */
	std::optional<ReportedRecognition> lastReported;
	/** Its scale, refined from later sightings ([vslam_scale_refinement]). */
	CLandmarkScaleTrack scale;

	/** Bytes this landmark takes in memory (points, their depth stds, descriptors, fields,
	 * the scale track's pairs). */
	size_t bytes() const
	{
		return sizeof(*this) + points.size() * sizeof(cv::Point3f) + depthStd.size() * sizeof(float) +
			descriptors.total() * descriptors.elemSize() + scale.bytes();
	}
};
}  // namespace vslam

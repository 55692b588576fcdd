#pragma once
/** \file LandmarkCreator.h
 * Builds a landmark from a few images taken along the robot's own motion.
 * The camera poses come from odometry and the camera mount (their only
 * source of scale); the image geometry refines them: features are matched
 * across the views, the relative rotation comes from the essential matrix
 * between the first and last view, points are triangulated, then bundle
 * adjustment refines points and poses with odometry as priors on the poses,
 * the scale is reset to the odometry baseline, and points that reproject
 * badly, lie behind a camera, are seen under too small an angle or too far
 * away are dropped. All views are assumed to come from the same camera
 * (the newest view's intrinsics are used).
 */
#include <libvslam/frontend/ImageFeatures.h>
#include <libvslam/frontend/TVisualFrontEndOptions.h>
#include <libvslam/frontend/VisualLandmarkModel.h>
#include <mrpt/poses/CPose3D.h>

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vslam
{
/** One image for landmark creation. */
struct CreationView
{
	ImageFeatures features;
	/** The camera in a common frame: robot pose from odometry composed with
	 * the camera mount (camera axes: z forward, x right, y down). */
	mrpt::poses::CPose3D cameraPose;
	double time = 0;
};

struct CreationResult
{
	std::optional<VisualLandmarkModel> landmark;  //!< no value: rejected
	std::string why;  //!< reason for a rejection
	int tracks = 0;  //!< features matched across all views
	int inliers = 0;  //!< points kept
	bool rotationFromImages = false;  //!< essential matrix used (else odometry only)
	/** Refined pose of each view's camera (in `views` order) relative to the
	 * newest camera: X_view = R X_newest + t; filled when built. */
	std::vector<std::pair<Eigen::Matrix3d, Eigen::Vector3d>> refinedPoses;
};

/** Builds a landmark whose frame is the robot frame of the newest view.
 * `mount` is the camera pose on the robot (the newest view's). */
CreationResult createLandmark(
	const std::vector<const CreationView*>& views, const mrpt::poses::CPose3D& mount,
	const TVisualFrontEndOptions& options);
}  // namespace vslam

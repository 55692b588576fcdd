#pragma once
/** \file RunScene.h
 * A run as MRPT's 3-D viewer shows it: final_map.3Dscene (SceneViewer3D)
 * with the estimated, odometry and (when given) true paths as lines, each
 * landmark with its 2-sigma position ellipse (a closed line), pose landmarks with a
 * tick along their heading, and the floor plan's walls and furniture as
 * outlines when the run has one. Colours as in vslam-eval's figures:
 * estimate blue, truth green, odometry red, landmarks black, floor plan
 * grey. Written atomically.
 */
#include <libvslam/io/Trajectory.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace vslam
{
struct RunSceneContent
{
	Trajectory estimated, odometry, truth;  //!< truth may be empty
	struct Landmark
	{
		se2::Pose pose;
		Eigen::Matrix2d positionCov;
		bool hasHeading = false;  //!< a pose landmark: its heading is drawn
	};
	std::vector<Landmark> landmarks;
	/** The floor plan's solid parts as closed outlines (may be empty). */
	std::vector<std::vector<Eigen::Vector2d>> floorPlan;
};

/** Writes the scene (MRPT's serialized COpenGLScene, gzip) to FILE.tmp and
 * renames it; throws OutputError. */
void writeRunScene(const std::string& file, const RunSceneContent& content);
}  // namespace vslam

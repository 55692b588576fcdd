#pragma once
/** \file SceneFaces.h
 * The flat parts of a world as MRPT scene objects: textured vertical faces
 * with rectangular holes (walls with their doorways and windows),
 * horizontal rectangles (floors, ceilings, tops) and plain boxes (frames,
 * sills, door casings). A photograph is mapped once over its face; a
 * material repeats at its size, aligned to the world's axes and heights so
 * tiles line up across faces.
 */
#include <libvslam/world/SurfaceTextures.h>
#include <mrpt/img/TColor.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CSetOfTexturedTriangles.h>

#include <Eigen/Core>
#include <vector>

namespace vslam::world
{
/** A rectangle of a vertical face: [s0, s1] metres from its start, [z0, z1] high. */
struct FaceRect
{
	double s0, s1, z0, z1;
};

/** The face from a to b, z0..z1 high, seen from the left of a -> b (the
 * image's left edge at b, as a viewer facing it sees it), minus holes. */
mrpt::opengl::CSetOfTexturedTriangles::Ptr verticalFace(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
	double z0, double z1, const std::vector<FaceRect>& holes, const SurfaceImage& surface);

/** The axis-aligned rectangle lo..hi at height z, seen from above (up) or below. */
mrpt::opengl::CSetOfTexturedTriangles::Ptr horizontalFace(
	const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double z, bool up, const SurfaceImage& surface);

/** A plain box: `length` along the direction `dir` from `start`, `depth`
 * towards `normal`, from z0 to z1. */
mrpt::opengl::CBox::Ptr plainBox(const Eigen::Vector2d& start, const Eigen::Vector2d& dir, double length,
	const Eigen::Vector2d& normal, double depth, double z0, double z1, const mrpt::img::TColor& colour);

/** The rectangles of [0, len] x [z0, z1] not covered by holes. */
std::vector<FaceRect> faceMinusHoles(double len, double z0, double z1, const std::vector<FaceRect>& holes);
}  // namespace vslam::world

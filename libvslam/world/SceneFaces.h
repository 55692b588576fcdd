#pragma once
/** \file SceneFaces.h
 * The flat parts of a world as MRPT scene objects: textured vertical faces
 * with rectangular holes (walls with their doorways and windows),
 * horizontal rectangles (floors, ceilings, tops), plain faces and plain
 * boxes (frames, sills, casings). A photograph is mapped once over its
 * face; a material repeats at its size, aligned to the world's axes and
 * heights so tiles line up across faces, and every face of one material
 * goes into one object: MRPT 2.5 gives each texture its own texture unit
 * (192 with Mesa), so a home must not have a texture per face.
 */
#include <libvslam/world/SurfaceTextures.h>
#include <mrpt/img/TColor.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CSetOfTexturedTriangles.h>
#include <mrpt/opengl/CSetOfTriangles.h>

#include <Eigen/Core>
#include <vector>

namespace vslam::world
{
/** A rectangle of a vertical face: [s0, s1] metres from its start, [z0, z1] high. */
struct FaceRect
{
	double s0, s1, z0, z1;
};

/** A textured object for one surface image (its texture assigned). */
mrpt::opengl::CSetOfTexturedTriangles::Ptr texturedSet(const SurfaceImage& surface);

/** Adds the face from a to b, z0..z1 high, seen from the left of a -> b
 * (the image's left edge at b, as a viewer facing it sees it), minus holes. */
void addVerticalFace(mrpt::opengl::CSetOfTexturedTriangles& set, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
	double z0, double z1, const std::vector<FaceRect>& holes, const SurfaceImage& surface);

/** Adds the axis-aligned rectangle lo..hi at height z, seen from above (up) or below. */
void addHorizontalFace(mrpt::opengl::CSetOfTexturedTriangles& set, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
	double z, bool up, const SurfaceImage& surface);

/** Adds a plain face of one colour from a to b, z0..z1, seen from the left. */
void addPlainFace(mrpt::opengl::CSetOfTriangles& set, const Eigen::Vector2d& a, const Eigen::Vector2d& b, double z0,
	double z1, const std::vector<FaceRect>& holes, const mrpt::img::TColor& colour);

/** A plain box: `length` along the direction `dir` from `start`, `depth`
 * towards `normal`, from z0 to z1. */
mrpt::opengl::CBox::Ptr plainBox(const Eigen::Vector2d& start, const Eigen::Vector2d& dir, double length,
	const Eigen::Vector2d& normal, double depth, double z0, double z1, const mrpt::img::TColor& colour);

/** The rectangles of [0, len] x [z0, z1] not covered by holes. */
std::vector<FaceRect> faceMinusHoles(double len, double z0, double z1, const std::vector<FaceRect>& holes);
}  // namespace vslam::world

#pragma once
/** \file WorldScene.h
 * The floor plan as an MRPT 3-D scene (mrpt::opengl::COpenGLScene): walls,
 * furniture, pictures and doors as textured planes carrying their
 * photographs at a fixed scale (no stretching: each surface shows a part
 * of its photograph with the surface's aspect ratio), a textured floor, a
 * plain ceiling, and people as moving cylinders with a head.
 */
#include <libvslam/world/FloorPlan.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <opencv2/core.hpp>

#include <map>
#include <string>
#include <vector>

namespace vslam::world
{
class WorldScene
{
   public:
	/** maxTextureSide: longest side of any texture, pixels. */
	WorldScene(const FloorPlan& plan, size_t peopleCount, int maxTextureSide = 2048);

	const mrpt::opengl::COpenGLScene& scene() const { return *m_scene; }

	/** Person i stands at p (visible) or is hidden. */
	void placePerson(size_t i, bool visible, const Eigen::Vector2d& p);

	static constexpr double kPersonRadius = 0.22, kPersonHeight = 1.75;

   private:
	mrpt::opengl::COpenGLScene::Ptr m_scene;
	std::vector<mrpt::opengl::CSetOfObjects::Ptr> m_people;
	std::map<std::string, cv::Mat> m_photos;
	int m_maxSide;

	const cv::Mat& photo(const std::string& file);
	/** The part of the texture for a surface of width x height metres:
	 * the largest piece of the chosen region with that aspect ratio, whose
	 * left edge starts at `along` (a fraction of the free width), scaled
	 * to at most m_maxSide pixels, rows flipped for OpenGL. */
	cv::Mat surfaceImage(const TextureRef& t, double width, double height, double along = 0.5);
	/** A vertical textured rectangle from a to b, z in [z0, z1], facing the
	 * left of a -> b. */
	void addVerticalFace(
		const Eigen::Vector2d& a, const Eigen::Vector2d& b, double z0, double z1, const cv::Mat& image);
	void addPlainVerticalFace(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double z0, double z1);
};
}  // namespace vslam::world

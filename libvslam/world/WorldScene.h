#pragma once
/** \file WorldScene.h
 * The floor plan as an MRPT 3-D scene (mrpt::opengl::COpenGLScene): walls
 * with their doorways (casings, open leaves) and windows (frames, sills, a
 * view outside behind the glass line), floors and ceiling, skirting boards,
 * catalogue furniture as 3-D models, boxes, framed pictures, door leaves,
 * and people as 3-D figures that walk through. Surfaces show photographs
 * at a fixed scale (never stretched) or materials tiled at their size.
 */
#include <libvslam/world/FloorPlan.h>
#include <libvslam/world/FurnitureModels.h>
#include <libvslam/world/SceneFaces.h>
#include <libvslam/world/SurfaceTextures.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/CSetOfTexturedTriangles.h>
#include <mrpt/opengl/CSetOfTriangles.h>

#include <map>
#include <string>
#include <vector>

namespace vslam::world
{
class WorldScene
{
   public:
	/** maxTextureSide: longest side of any photograph's texture, pixels. */
	WorldScene(const FloorPlan& plan, size_t peopleCount, int maxTextureSide = 2048);

	const mrpt::opengl::COpenGLScene& scene() const { return *m_scene; }

	/** Person i stands at p facing `heading` (visible) or is hidden. */
	void placePerson(size_t i, bool visible, const Eigen::Vector2d& p, double heading = 0);

	/** What the laser and the path planning take a person for. */
	static constexpr double kPersonRadius = 0.25;

   private:
	const FloorPlan& m_plan;
	mrpt::opengl::COpenGLScene::Ptr m_scene;
	SurfaceTextures m_textures;
	FurnitureModels m_furniture;
	std::vector<mrpt::opengl::CSetOfObjects::Ptr> m_people;
	std::map<int, mrpt::opengl::CSetOfTexturedTriangles::Ptr> m_materialFaces;  //!< by material
	mrpt::opengl::CSetOfTriangles::Ptr m_plainFaces;

	/** The object a surface showing `t` goes into (one per material, a new
	 * one per photograph) and the image mapped on it. */
	std::pair<mrpt::opengl::CSetOfTexturedTriangles*, SurfaceImage> faceFor(
		const TextureRef& t, double width, double height, double along = 0.5);
	void addFace(const TextureRef& t, const Eigen::Vector2d& a, const Eigen::Vector2d& b, double z0, double z1,
		const std::vector<FaceRect>& holes = {}, double along = 0.5);

	void addWalls();
	void addOpenings();
	void addFloorAndCeiling();
	void addBoxes();
	void addFurniture();
	void addPictures();
	void addDoors();
	void addSkirting();
	void addPeople(size_t count);
	void insert(const mrpt::opengl::CRenderizable::Ptr& object);
};
}  // namespace vslam::world

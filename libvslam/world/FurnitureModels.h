#pragma once
/** \file FurnitureModels.h
 * Catalogue furniture as MRPT scene objects (mrpt::opengl::CAssimpModel,
 * which reads the OBJ models with their materials and textures), each
 * model loaded once and fitted to its item's size: its bounding box
 * scaled to width x depth x height, its front (+z of Sweet Home 3D's
 * y-up models) turned to the direction given, its base at the elevation.
 */
#include <libvslam/world/FurnitureCatalog.h>
#include <mrpt/opengl/CSetOfObjects.h>

#include <Eigen/Core>
#include <map>
#include <string>

namespace vslam::world
{
class FurnitureModels
{
   public:
	/** textureDir: the folder the items' model paths are relative to. */
	explicit FurnitureModels(std::string textureDir);

	/** `item` standing with the centre of its footprint at `centre`, its
	 * front facing the direction `facing` (rad), its base `elevation` m
	 * above the floor. Copies of one item share the loaded model. */
	mrpt::opengl::CSetOfObjects::Ptr place(
		const FurnitureItem& item, const Eigen::Vector2d& centre, double facing, double elevation);

   private:
	std::string m_textureDir;
	std::map<std::string, mrpt::opengl::CRenderizable::Ptr> m_fitted;  //!< by item name

	/** The model fitted to the item's size, in a frame whose origin is the
	 * centre of its footprint on the floor, its front facing -y. */
	const mrpt::opengl::CRenderizable::Ptr& fitted(const FurnitureItem& item);
};
}  // namespace vslam::world

/** Every catalogue model loads from the package and is fitted to its
 * catalogue size: its bounding box in the scene spans width x depth x
 * height, stands on its elevation, and its front faces the direction it
 * was given. Skipped when sweethome3d-furniture is not installed. */
#include <gtest/gtest.h>
#include <libvslam/world/FurnitureModels.h>
#include <mrpt/poses/CPose3D.h>

#include <filesystem>

using namespace vslam::world;

namespace
{
const std::string kTextures = "/usr/share";

bool packageInstalled() { return std::filesystem::is_directory(kTextures + "/" + kFurnitureArchiveDir); }

/** The placed model's bounding box in the scene: its own box through its
 * scale, its pose and its holder's pose (MRPT's bounding boxes leave the
 * scale out). */
mrpt::math::TBoundingBox sceneBox(const mrpt::opengl::CSetOfObjects& holder)
{
	const auto& model = *holder.begin();
	const auto local = model->getBoundingBoxLocal();
	mrpt::math::TBoundingBox out = mrpt::math::TBoundingBox::PlusMinusInfinity();
	for (int c = 0; c < 8; c++)
	{
		const mrpt::math::TPoint3D p(model->getScaleX() * (c & 1 ? local.max.x : local.min.x),
			model->getScaleY() * (c & 2 ? local.max.y : local.min.y), model->getScaleZ() * (c & 4 ? local.max.z : local.min.z));
		const auto q = holder.getPoseRef().composePoint(model->getPoseRef().composePoint(p));
		out.updateWithPoint(q);
	}
	return out;
}
}  // namespace

TEST(FurnitureModels, EveryCatalogueModelLoadsAtItsSize)
{
	if (!packageInstalled()) GTEST_SKIP() << "sweethome3d-furniture is not installed (scripts/setup.sh installs it)";
	FurnitureModels models(kTextures);
	for (const FurnitureItem& item : furnitureCatalog())
	{
		SCOPED_TRACE(item.name);
		mrpt::opengl::CSetOfObjects::Ptr placed;
		ASSERT_NO_THROW(placed = models.place(item, {2, 3}, 0, 0.5));  // facing +x
		const auto box = sceneBox(*placed);
		// Facing +x: its depth runs along x, its width along y.
		EXPECT_NEAR(box.max.x - box.min.x, item.depth, 0.01 * item.depth + 1e-3);
		EXPECT_NEAR(box.max.y - box.min.y, item.width, 0.01 * item.width + 1e-3);
		EXPECT_NEAR(box.max.z - box.min.z, item.height, 0.01 * item.height + 1e-3);
		EXPECT_NEAR(0.5 * (box.min.x + box.max.x), 2, 1e-3);
		EXPECT_NEAR(0.5 * (box.min.y + box.max.y), 3, 1e-3);
		EXPECT_NEAR(box.min.z, 0.5, 1e-3);
	}
}

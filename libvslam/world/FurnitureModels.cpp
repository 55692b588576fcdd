#include <libvslam/core/InputError.h>
#include <libvslam/world/AssetArchive.h>
#include <libvslam/world/FurnitureModels.h>
#include <mrpt/opengl/CAssimpModel.h>
#include <mrpt/poses/CPose3D.h>

#include <Eigen/Dense>
#include <cmath>

namespace vslam::world
{
namespace
{
/** Sweet Home 3D's models are y-up with their front towards +z; the scene
 * is z-up: model x stays x, model y becomes z, model z becomes -y. */
Eigen::Matrix3d yUpToZUp()
{
	Eigen::Matrix3d r;
	r << 1, 0, 0, 0, 0, -1, 0, 1, 0;
	return r;
}

Eigen::Matrix3d modelRotation(const FurnitureItem& item)
{
	if (item.modelRotation.empty()) return Eigen::Matrix3d::Identity();
	Eigen::Matrix3d r;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++) r(i, j) = item.modelRotation[static_cast<size_t>(3 * i + j)];
	return r;
}

mrpt::opengl::CAssimpModel::Ptr loadModel(const std::string& file, const FurnitureItem& item)
{
	const std::optional<AssetLocation> at = locateAsset(file);
	if (!at) throw InputError("furniture '" + item.name + "': no model '" + file + "' (is sweethome3d-furniture installed?)");
	const ExtractedAsset local(*at);
	auto model = mrpt::opengl::CAssimpModel::Create();
	try
	{
		using Flags = mrpt::opengl::CAssimpModel::LoadFlags;
		model->loadScene(local.path(), Flags::RealTimeMaxQuality | Flags::FlipUVs);
	}
	catch (const std::exception& e)
	{
		throw InputError("furniture '" + item.name + "': cannot load model '" + file + "': " + e.what());
	}
	return model;
}
}  // namespace

FurnitureModels::FurnitureModels(std::string textureDir) : m_textureDir(std::move(textureDir)) {}

const mrpt::opengl::CRenderizable::Ptr& FurnitureModels::fitted(const FurnitureItem& item)
{
	auto it = m_fitted.find(item.name);
	if (it != m_fitted.end()) return it->second;
	auto model = loadModel(m_textureDir + "/" + item.model, item);
	const auto box = model->getBoundingBoxLocal();
	const Eigen::Matrix3d rm = modelRotation(item);
	Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;  // of the rotated model
	for (int c = 0; c < 8; c++)
	{
		const Eigen::Vector3d corner(
			c & 1 ? box.max.x : box.min.x, c & 2 ? box.max.y : box.min.y, c & 4 ? box.max.z : box.min.z);
		lo = lo.cwiseMin(rm * corner), hi = hi.cwiseMax(rm * corner);
	}
	const Eigen::Vector3d extent = hi - lo, target(item.width, item.height, item.depth);  // model axes x, y, z
	if (!(extent.maxCoeff() > 0))
		throw InputError("furniture '" + item.name + "': the model '" + item.model + "' is empty");
	// Each model axis is scaled by the size along the axis it is rotated onto.
	Eigen::Vector3d scale;
	for (int i = 0; i < 3; i++)
	{
		Eigen::Index k = 0;
		rm.col(i).cwiseAbs().maxCoeff(&k);
		scale[i] = extent[k] > 1e-9 ? target[k] / extent[k] : 1.0;
	}
	const Eigen::Matrix3d r = yUpToZUp() * rm;
	const Eigen::Vector3d baseCentre = rm.transpose() * Eigen::Vector3d(0.5 * (lo.x() + hi.x()), lo.y(), 0.5 * (lo.z() + hi.z()));
	const Eigen::Vector3d t = -r * scale.cwiseProduct(baseCentre);
	mrpt::math::CMatrixDouble44 h = mrpt::math::CMatrixDouble44::Identity();
	for (int i = 0; i < 3; i++)
	{
		for (int j = 0; j < 3; j++) h(i, j) = r(i, j);
		h(i, 3) = t[i];
	}
	model->setPose(mrpt::poses::CPose3D(h));
	model->setScale(static_cast<float>(scale[0]), static_cast<float>(scale[1]), static_cast<float>(scale[2]));
	return m_fitted.emplace(item.name, model).first->second;
}

mrpt::opengl::CSetOfObjects::Ptr FurnitureModels::place(
	const FurnitureItem& item, const Eigen::Vector2d& centre, double facing, double elevation)
{
	auto holder = mrpt::opengl::CSetOfObjects::Create();
	holder->insert(fitted(item));
	// The fitted model faces -y: turn it by facing + 90 deg.
	holder->setPose(mrpt::poses::CPose3D(centre[0], centre[1], elevation, facing + M_PI / 2, 0, 0));
	return holder;
}
}  // namespace vslam::world

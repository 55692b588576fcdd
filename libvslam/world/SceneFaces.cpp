#include <libvslam/world/SceneFaces.h>
#include <mrpt/img/CImage.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>

namespace vslam::world
{
namespace
{
using Triangle = mrpt::opengl::TTriangle;

/** A quad p0 p1 p2 p3 (counter-clockwise seen from its front) with its UVs
 * and vertex colour. */
template <class Set>
void addQuad(Set& set, const std::array<Eigen::Vector3d, 4>& p, const std::array<Eigen::Vector2d, 4>& uv,
	const Eigen::Vector3d& normal, const mrpt::img::TColor& colour = {255, 255, 255})
{
	for (const auto& idx : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}})
	{
		Triangle t;
		for (int k = 0; k < 3; k++)
		{
			auto& v = t.vertices[static_cast<size_t>(k)];
			const auto& q = p[static_cast<size_t>(idx[static_cast<size_t>(k)])];
			v.xyzrgba.pt = {static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z())};
			v.setColor(colour);
			const auto& w = uv[static_cast<size_t>(idx[static_cast<size_t>(k)])];
			v.uv = {static_cast<float>(w.x()), static_cast<float>(w.y())};
			v.normal = {static_cast<float>(normal.x()), static_cast<float>(normal.y()), static_cast<float>(normal.z())};
		}
		set.insertTriangle(t);
	}
}
}  // namespace

mrpt::opengl::CSetOfTexturedTriangles::Ptr texturedSet(const SurfaceImage& surface)
{
	auto set = mrpt::opengl::CSetOfTexturedTriangles::Create();
	set->assignImage(mrpt::img::CImage(surface.image, mrpt::img::DEEP_COPY));
	set->enableTextureLinearInterpolation(true);
	return set;
}

std::vector<FaceRect> faceMinusHoles(double len, double z0, double z1, const std::vector<FaceRect>& holes)
{
	std::vector<double> cuts{0, len};
	for (const FaceRect& h : holes)
		for (double s : {h.s0, h.s1})
			if (s > 0 && s < len) cuts.push_back(s);
	std::sort(cuts.begin(), cuts.end());
	cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
	std::vector<FaceRect> out;
	for (size_t c = 0; c + 1 < cuts.size(); c++)
	{
		const double s0 = cuts[c], s1 = cuts[c + 1], mid = 0.5 * (s0 + s1);
		std::vector<std::pair<double, double>> blocked;
		for (const FaceRect& h : holes)
			if (h.s0 < mid && mid < h.s1) blocked.emplace_back(std::max(h.z0, z0), std::min(h.z1, z1));
		std::sort(blocked.begin(), blocked.end());
		double z = z0;
		for (const auto& [b0, b1] : blocked)
		{
			if (b0 > z) out.push_back({s0, s1, z, b0});
			z = std::max(z, b1);
		}
		if (z < z1) out.push_back({s0, s1, z, z1});
	}
	return out;
}

void addVerticalFace(mrpt::opengl::CSetOfTexturedTriangles& set, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
	double z0, double z1, const std::vector<FaceRect>& holes, const SurfaceImage& surface)
{
	const double len = (b - a).norm();
	if (len < 1e-9) return;
	const Eigen::Vector2d d = (b - a) / len;
	const Eigen::Vector3d normal(-d[1], d[0], 0);
	const auto point = [&](double s, double z) { return Eigen::Vector3d(a[0] + s * d[0], a[1] + s * d[1], z); };
	const auto uv = [&](double s, double z) -> Eigen::Vector2d {
		if (surface.tiled) return {(len - s) / surface.tileWidth, z / surface.tileHeight};
		return {(len - s) / len, (z - z0) / (z1 - z0)};
	};
	for (const FaceRect& r : faceMinusHoles(len, z0, z1, holes))
		addQuad(set, {point(r.s0, r.z0), point(r.s0, r.z1), point(r.s1, r.z1), point(r.s1, r.z0)},
			{uv(r.s0, r.z0), uv(r.s0, r.z1), uv(r.s1, r.z1), uv(r.s1, r.z0)}, normal);
}

void addPlainFace(mrpt::opengl::CSetOfTriangles& set, const Eigen::Vector2d& a, const Eigen::Vector2d& b, double z0,
	double z1, const std::vector<FaceRect>& holes, const mrpt::img::TColor& colour)
{
	const double len = (b - a).norm();
	if (len < 1e-9) return;
	const Eigen::Vector2d d = (b - a) / len;
	const Eigen::Vector3d normal(-d[1], d[0], 0);
	const auto point = [&](double s, double z) { return Eigen::Vector3d(a[0] + s * d[0], a[1] + s * d[1], z); };
	const Eigen::Vector2d none(0, 0);
	for (const FaceRect& r : faceMinusHoles(len, z0, z1, holes))
		addQuad(set, {point(r.s0, r.z0), point(r.s0, r.z1), point(r.s1, r.z1), point(r.s1, r.z0)}, {none, none, none, none},
			normal, colour);
}

void addHorizontalFace(mrpt::opengl::CSetOfTexturedTriangles& set, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
	double z, bool up, const SurfaceImage& surface)
{
	const auto point = [&](double x, double y) { return Eigen::Vector3d(x, y, z); };
	const auto uv = [&](double x, double y) -> Eigen::Vector2d {
		if (surface.tiled) return {x / surface.tileWidth, y / surface.tileHeight};
		return {(x - lo[0]) / (hi[0] - lo[0]), (y - lo[1]) / (hi[1] - lo[1])};
	};
	std::array<Eigen::Vector3d, 4> p{point(lo[0], lo[1]), point(hi[0], lo[1]), point(hi[0], hi[1]), point(lo[0], hi[1])};
	std::array<Eigen::Vector2d, 4> w{uv(lo[0], lo[1]), uv(hi[0], lo[1]), uv(hi[0], hi[1]), uv(lo[0], hi[1])};
	if (!up) std::swap(p[1], p[3]), std::swap(w[1], w[3]);
	addQuad(set, p, w, Eigen::Vector3d(0, 0, up ? 1 : -1));
}

mrpt::opengl::CBox::Ptr plainBox(const Eigen::Vector2d& start, const Eigen::Vector2d& dir, double length,
	const Eigen::Vector2d& normal, double depth, double z0, double z1, const mrpt::img::TColor& colour)
{
	// In the box's own frame x runs along dir and y to its left.
	const double y = normal.dot(Eigen::Vector2d(-dir[1], dir[0])) >= 0 ? depth : -depth;
	auto box = mrpt::opengl::CBox::Create(
		mrpt::math::TPoint3D(0, std::min(0.0, y), z0), mrpt::math::TPoint3D(length, std::max(0.0, y), z1));
	box->setPose(mrpt::poses::CPose3D(start[0], start[1], 0, std::atan2(dir[1], dir[0]), 0, 0));
	box->setColor_u8(colour);
	return box;
}
}  // namespace vslam::world

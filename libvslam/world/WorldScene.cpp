#include <libvslam/world/SceneFaces.h>
#include <libvslam/world/WorldScene.h>
#include <mrpt/img/CImage.h>
#include <mrpt/opengl/CTexturedPlane.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>

namespace vslam::world
{
namespace
{
const mrpt::img::TColor kPaint(236, 234, 228), kFrame(70, 52, 40), kWhiteFrame(232, 232, 226);

/** A one-colour surface (the unpapered side of a wall). */
SurfaceImage plain(const mrpt::img::TColor& c)
{
	SurfaceImage s;
	s.image = cv::Mat(2, 2, CV_8UC3, cv::Scalar(c.B, c.G, c.R));
	return s;
}

Eigen::Vector2d leftOf(const Eigen::Vector2d& d) { return {-d[1], d[0]}; }

/** Wall i's holes, measured from `reversed` ? its end : its start. */
std::vector<FaceRect> holesOf(const FloorPlan& plan, size_t i, bool reversed)
{
	const double len = (plan.walls[i].b - plan.walls[i].a).norm();
	std::vector<FaceRect> out;
	for (const Opening* o : plan.openingsOf(i))
		out.push_back(reversed ? FaceRect{len - o->s1, len - o->s0, o->z0, o->z1} : FaceRect{o->s0, o->s1, o->z0, o->z1});
	return out;
}
}  // namespace

WorldScene::WorldScene(const FloorPlan& plan, size_t peopleCount, int maxTextureSide)
	: m_plan(plan),
	  m_scene(mrpt::opengl::COpenGLScene::Create()),
	  m_textures(plan, maxTextureSide),
	  m_furniture(plan.textureDir)
{
	// Mostly diffuse light from above (MRPT has one directional light):
	// walls differ in brightness by their facing as in a real room, and the
	// floor, lit most, stays below saturation.
	auto& light = m_scene->getViewport()->lightParameters();
	light.ambient = {0.6f, 0.6f, 0.6f, 1};
	light.diffuse = {0.4f, 0.4f, 0.4f, 1};
	light.specular = {0.1f, 0.1f, 0.1f, 1};
	light.direction = mrpt::math::TVector3Df(-0.25f, -0.35f, -0.9f).unitarize();
	m_scene->getViewport()->setCustomBackgroundColor({0.78f, 0.84f, 0.9f, 1});
	addFloorAndCeiling();
	addWalls();
	addOpenings();
	addSkirting();
	addBoxes();
	addFurniture();
	addPictures();
	addDoors();
	addPeople(peopleCount);
}

void WorldScene::insert(const mrpt::opengl::CRenderizable::Ptr& object) { m_scene->insert(object); }

void WorldScene::addWalls()
{
	const double H = m_plan.ceilingHeight;
	for (size_t i = 0; i < m_plan.walls.size(); i++)
	{
		const Wall& w = m_plan.walls[i];
		const double len = (w.b - w.a).norm();
		const Eigen::Vector2d off = 0.5 * w.thickness * leftOf((w.b - w.a) / len);
		insert(verticalFace(w.a + off, w.b + off, 0, H, holesOf(m_plan, i, false), m_textures.surface(w.front, len, H)));
		insert(verticalFace(w.b - off, w.a - off, 0, H, holesOf(m_plan, i, true),
			w.hasBack ? m_textures.surface(w.back, len, H) : plain(kPaint)));
		for (const auto& [s0, s1] : m_plan.wallPieces(i))  // the cut ends, seen from the doorways
		{
			const Eigen::Vector2d a = alongWall(w, s0), b = alongWall(w, s1);
			insert(verticalFace(a - off, a + off, 0, H, {}, plain(kPaint)));
			insert(verticalFace(b + off, b - off, 0, H, {}, plain(kPaint)));
		}
	}
}

void WorldScene::addOpenings()
{
	size_t windows = 0;
	for (const Opening& o : m_plan.openings)
	{
		const Wall& w = m_plan.walls[o.wall];
		const Eigen::Vector2d d = (w.b - w.a).normalized(), n = leftOf(d);
		const double t = w.thickness, width = o.s1 - o.s0;
		const Eigen::Vector2d a = alongWall(w, o.s0), b = alongWall(w, o.s1);
		// Soffit (and sill) across the wall's thickness.
		insert(plainBox(a - 0.5 * t * n, d, width, n, t, o.z1, o.z1 + 0.01, kPaint));
		if (o.kind == Opening::Kind::Window)
		{
			// Jambs, a sill board standing out into the room, a mullion in
			// the glass line, and the view far outside.
			insert(plainBox(a - 0.5 * t * n - 0.01 * d, d, 0.01, n, t, o.z0, o.z1, kPaint));
			insert(plainBox(b - 0.5 * t * n, d, 0.01, n, t, o.z0, o.z1, kPaint));
			insert(plainBox(a - 0.5 * t * n - 0.05 * d, d, width + 0.1, n, t + 0.06, o.z0 - 0.03, o.z0, kWhiteFrame));
			insert(plainBox(a + 0.5 * (width - 0.05) * d, d, 0.05, n, 0.05, o.z0, o.z1, kWhiteFrame));
			const double D = 5.0 + 0.05 * static_cast<double>(windows++);
			const Eigen::Vector2d viewA = a - (0.5 * t + D) * n - 1.6 * D * d, viewB = b - (0.5 * t + D) * n + 1.6 * D * d;
			const double z0 = o.z0 - 0.8 * D, z1 = o.z1 + 0.5 * D;
			insert(verticalFace(viewA, viewB, z0, z1, {}, m_textures.surface(o.texture, (viewB - viewA).norm(), z1 - z0)));
		}
		for (const double side : {1.0, -1.0})  // casings on both faces
		{
			const Eigen::Vector2d face = (0.5 * t) * side * n;
			insert(plainBox(a + face - 0.06 * d, d, 0.06, side * n, 0.015, o.z0, o.z1 + 0.06, kWhiteFrame));
			insert(plainBox(b + face, d, 0.06, side * n, 0.015, o.z0, o.z1 + 0.06, kWhiteFrame));
			insert(plainBox(a + face - 0.06 * d, d, width + 0.12, side * n, 0.015, o.z1, o.z1 + 0.06, kWhiteFrame));
		}
		if (o.kind == Opening::Kind::Doorway && o.hasLeaf)
		{
			const auto [hinge, end] = doorLeaf(m_plan, o);
			const Eigen::Vector2d ld = (end - hinge).normalized(), ln = leftOf(ld);
			const double len = (end - hinge).norm(), h = o.z1 - 0.01;
			insert(verticalFace(hinge + 0.02 * ln, end + 0.02 * ln, 0, h, {}, m_textures.surface(o.texture, len, h, 0.0)));
			insert(verticalFace(end - 0.02 * ln, hinge - 0.02 * ln, 0, h, {}, m_textures.surface(o.texture, len, h, 1.0)));
		}
	}
}

void WorldScene::addFloorAndCeiling()
{
	const auto [lo, hi] = m_plan.bounds();
	insert(horizontalFace(lo, hi, 0, true,
		m_plan.hasFloorTexture ? m_textures.surface(m_plan.floor, hi[0] - lo[0], hi[1] - lo[1]) : plain({150, 140, 125})));
	for (size_t k = 0; k < m_plan.floorAreas.size(); k++)
	{
		const FloorArea& a = m_plan.floorAreas[k];
		insert(horizontalFace(a.lo, a.hi, 0.001 * static_cast<double>(k + 1), true,
			m_textures.surface(a.texture, a.hi[0] - a.lo[0], a.hi[1] - a.lo[1])));
	}
	insert(horizontalFace(lo, hi, m_plan.ceilingHeight, false,
		m_plan.hasCeilingTexture ? m_textures.surface(m_plan.ceiling, hi[0] - lo[0], hi[1] - lo[1]) : plain({235, 235, 228})));
}

void WorldScene::addSkirting()
{
	if (m_plan.skirtingHeight <= 0) return;
	const double h = m_plan.skirtingHeight;
	for (size_t i = 0; i < m_plan.walls.size(); i++)
	{
		const Wall& w = m_plan.walls[i];
		const Eigen::Vector2d d = (w.b - w.a).normalized(), n = leftOf(d);
		for (const auto& [s0, s1] : m_plan.wallPieces(i))
			for (const double side : {1.0, -1.0})
			{
				const Eigen::Vector2d off = (0.5 * w.thickness + 0.012) * side * n;
				Eigen::Vector2d a = alongWall(w, s0) + off, b = alongWall(w, s1) + off;
				if (side < 0) std::swap(a, b);
				insert(verticalFace(a, b, 0, h, {}, m_textures.surface(m_plan.skirting, s1 - s0, h)));
			}
	}
}

void WorldScene::addBoxes()
{
	for (const Box& b : m_plan.boxes)
	{
		// The photograph's chosen region is wrapped around the box's sides.
		const auto c = footprint(b);
		const double perimeter = 2 * (b.sizeX + b.sizeY);
		const SurfaceImage wrap = m_textures.surface(b.texture, perimeter, b.height);
		double start = 0;
		for (size_t i = 0; i < 4; i++)
		{
			const double len = (c[(i + 1) % 4] - c[i]).norm();
			SurfaceImage side = wrap;
			if (!wrap.tiled)
			{
				const int x0 = static_cast<int>(std::round(start / perimeter * wrap.image.cols));
				const int x1 = std::max(x0 + 1, static_cast<int>(std::round((start + len) / perimeter * wrap.image.cols)));
				side.image = wrap.image.colRange(x0, std::min(x1, wrap.image.cols)).clone();
			}
			start += len;
			insert(verticalFace(c[i], c[(i + 1) % 4], 0, b.height, {}, side));
		}
		auto top = mrpt::opengl::CTexturedPlane::Create(-b.sizeX / 2, b.sizeX / 2, -b.sizeY / 2, b.sizeY / 2);
		top->assignImage(mrpt::img::CImage(m_textures.surface(b.texture, b.sizeX, b.sizeY, 0.0).image, mrpt::img::DEEP_COPY));
		top->enableTextureLinearInterpolation(true);
		top->setPose(mrpt::poses::CPose3D(b.centre[0], b.centre[1], b.height, b.yaw, 0, 0));
		insert(top);
	}
}

void WorldScene::addFurniture()
{
	for (const Furniture& f : m_plan.furniture) insert(m_furniture.place(*f.item, f.centre, f.facing, f.elevation));
}

void WorldScene::addPictures()
{
	for (const Picture& q : m_plan.pictures)
	{
		const double len = (q.b - q.a).norm();
		const Eigen::Vector2d d = (q.b - q.a) / len, n = leftOf(d);
		insert(verticalFace(q.a + 0.02 * n, q.b + 0.02 * n, q.z0, q.z1, {}, m_textures.surface(q.texture, len, q.z1 - q.z0)));
		if (!q.framed) continue;
		const double f = 0.025;  // the frame around it
		insert(plainBox(q.a - f * d, d, f, n, 0.025, q.z0 - f, q.z1 + f, kFrame));
		insert(plainBox(q.b, d, f, n, 0.025, q.z0 - f, q.z1 + f, kFrame));
		insert(plainBox(q.a, d, len, n, 0.025, q.z0 - f, q.z0, kFrame));
		insert(plainBox(q.a, d, len, n, 0.025, q.z1, q.z1 + f, kFrame));
	}
}

void WorldScene::addDoors()
{
	for (const Door& door : m_plan.doors)
	{
		const Eigen::Vector2d d = (door.b - door.a).normalized(), n = leftOf(d);
		const double len = (door.b - door.a).norm(), h = std::min(door.height, m_plan.ceilingHeight);
		insert(verticalFace(door.a + 0.02 * n, door.b + 0.02 * n, 0, h, {}, m_textures.surface(door.texture, len, h, 0.0)));
		insert(verticalFace(door.b - 0.02 * n, door.a - 0.02 * n, 0, h, {}, m_textures.surface(door.texture, len, h, 1.0)));
	}
}

void WorldScene::addPeople(size_t count)
{
	const auto figures = furnitureOfRole(FurnitureRole::Person);
	for (size_t i = 0; i < count; i++)
	{
		auto person = m_furniture.place(*figures[i % figures.size()], {0, 0}, 0, 0);
		person->setVisibility(false);
		insert(person);
		m_people.push_back(person);
	}
}

void WorldScene::placePerson(size_t i, bool visible, const Eigen::Vector2d& p, double heading)
{
	auto& person = m_people.at(i);
	person->setVisibility(visible);
	person->setPose(mrpt::poses::CPose3D(p[0], p[1], 0, heading + M_PI / 2, 0, 0));
}
}  // namespace vslam::world

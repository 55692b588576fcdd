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
	  m_furniture(plan.textureDir),
	  m_plainFaces(mrpt::opengl::CSetOfTriangles::Create())
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
	insert(m_plainFaces);
	m_textures.release();  // full-size photographs: a few hundred MB in a decorated home
}

void WorldScene::insert(const mrpt::opengl::CRenderizable::Ptr& object) { m_scene->insert(object); }

std::pair<mrpt::opengl::CSetOfTexturedTriangles*, SurfaceImage> WorldScene::faceFor(
	const TextureRef& t, double width, double height, double along)
{
	SurfaceImage surface = m_textures.surface(t, width, height, along);
	if (t.material < 0)
	{
		auto set = texturedSet(surface);
		insert(set);
		return {set.get(), surface};
	}
	auto& set = m_materialFaces[t.material];
	if (!set)
	{
		set = texturedSet(surface);
		insert(set);
	}
	return {set.get(), surface};
}

void WorldScene::addFace(const TextureRef& t, const Eigen::Vector2d& a, const Eigen::Vector2d& b, double z0, double z1,
	const std::vector<FaceRect>& holes, double along)
{
	const auto [set, surface] = faceFor(t, (b - a).norm(), z1 - z0, along);
	addVerticalFace(*set, a, b, z0, z1, holes, surface);
}

void WorldScene::addWalls()
{
	const double H = m_plan.ceilingHeight;
	for (size_t i = 0; i < m_plan.walls.size(); i++)
	{
		const Wall& w = m_plan.walls[i];
		const double len = (w.b - w.a).norm();
		const Eigen::Vector2d off = 0.5 * w.thickness * leftOf((w.b - w.a) / len);
		addFace(w.front, w.a + off, w.b + off, 0, H, holesOf(m_plan, i, false));
		if (w.hasBack)
			addFace(w.back, w.b - off, w.a - off, 0, H, holesOf(m_plan, i, true));
		else
			addPlainFace(*m_plainFaces, w.b - off, w.a - off, 0, H, holesOf(m_plan, i, true), kPaint);
		for (const auto& [s0, s1] : m_plan.wallPieces(i))  // the cut ends, seen from the doorways
		{
			const Eigen::Vector2d a = alongWall(w, s0), b = alongWall(w, s1);
			addPlainFace(*m_plainFaces, a - off, a + off, 0, H, {}, kPaint);
			addPlainFace(*m_plainFaces, b + off, b - off, 0, H, {}, kPaint);
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
			addFace(o.texture, viewA, viewB, o.z0 - 0.8 * D, o.z1 + 0.5 * D);
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
			const double h = o.z1 - 0.01;
			addFace(o.texture, hinge + 0.02 * ln, end + 0.02 * ln, 0, h, {}, 0.0);
			addFace(o.texture, end - 0.02 * ln, hinge - 0.02 * ln, 0, h, {}, 1.0);
		}
	}
}

void WorldScene::addFloorAndCeiling()
{
	const auto [lo, hi] = m_plan.bounds();
	const auto horizontal = [&](const TextureRef& t, const Eigen::Vector2d& a, const Eigen::Vector2d& b, double z, bool up) {
		const auto [set, surface] = faceFor(t, b[0] - a[0], b[1] - a[1]);
		addHorizontalFace(*set, a, b, z, up, surface);
	};
	if (m_plan.hasFloorTexture)
		horizontal(m_plan.floor, lo, hi, 0, true);
	else
	{
		auto floor = mrpt::opengl::CTexturedPlane::Create(lo[0], hi[0], lo[1], hi[1]);
		floor->setColor_u8(150, 140, 125);
		insert(floor);
	}
	for (size_t k = 0; k < m_plan.floorAreas.size(); k++)
	{
		const FloorArea& a = m_plan.floorAreas[k];
		horizontal(a.texture, a.lo, a.hi, 0.001 * static_cast<double>(k + 1), true);
	}
	if (m_plan.hasCeilingTexture)
		horizontal(m_plan.ceiling, lo, hi, m_plan.ceilingHeight, false);
	else
	{
		auto ceiling = mrpt::opengl::CTexturedPlane::Create(lo[0], hi[0], lo[1], hi[1]);
		ceiling->setColor_u8(235, 235, 228);
		ceiling->setLocation(0, 0, m_plan.ceilingHeight);
		insert(ceiling);
	}
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
				addFace(m_plan.skirting, a, b, 0, h);
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
		const auto [wrapSet, wrap] = faceFor(b.texture, perimeter, b.height);
		double start = 0;
		for (size_t i = 0; i < 4; i++)
		{
			const double len = (c[(i + 1) % 4] - c[i]).norm();
			if (wrap.tiled)
				addVerticalFace(*wrapSet, c[i], c[(i + 1) % 4], 0, b.height, {}, wrap);
			else
			{
				SurfaceImage side = wrap;
				const int x0 = static_cast<int>(std::round(start / perimeter * wrap.image.cols));
				const int x1 = std::max(x0 + 1, static_cast<int>(std::round((start + len) / perimeter * wrap.image.cols)));
				side.image = wrap.image.colRange(x0, std::min(x1, wrap.image.cols)).clone();
				auto set = texturedSet(side);
				addVerticalFace(*set, c[i], c[(i + 1) % 4], 0, b.height, {}, side);
				insert(set);
			}
			start += len;
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
		addFace(q.texture, q.a + 0.02 * n, q.b + 0.02 * n, q.z0, q.z1);
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
		const double h = std::min(door.height, m_plan.ceilingHeight);
		addFace(door.texture, door.a + 0.02 * n, door.b + 0.02 * n, 0, h, {}, 0.0);
		addFace(door.texture, door.b - 0.02 * n, door.a - 0.02 * n, 0, h, {}, 1.0);
	}
}

void WorldScene::addPeople(size_t count)
{
	// Three figures at most, shared by everyone walking through: every
	// model's textures take texture units of their own.
	const auto figures = furnitureOfRole(FurnitureRole::Person);
	const size_t kinds = std::min<size_t>(3, figures.size());
	for (size_t i = 0; i < count; i++)
	{
		auto person = m_furniture.place(*figures[(i % kinds) * figures.size() / kinds], {0, 0}, 0, 0);
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

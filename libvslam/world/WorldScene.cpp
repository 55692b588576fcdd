#include <libvslam/core/InputError.h>
#include <libvslam/world/WorldScene.h>
#include <mrpt/img/CImage.h>
#include <mrpt/opengl/CCylinder.h>
#include <mrpt/opengl/CSphere.h>
#include <mrpt/opengl/CTexturedPlane.h>
#include <mrpt/poses/CPose3D.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>

namespace vslam::world
{
namespace
{
mrpt::img::CImage toCImage(const cv::Mat& m) { return mrpt::img::CImage(m, mrpt::img::DEEP_COPY); }
}  // namespace

WorldScene::WorldScene(const FloorPlan& plan, size_t peopleCount, int maxTextureSide)
	: m_scene(mrpt::opengl::COpenGLScene::Create()), m_maxSide(maxTextureSide)
{
	const double H = plan.ceilingHeight;
	for (const Wall& w : plan.walls)
	{
		const double len = (w.b - w.a).norm();
		const Eigen::Vector2d d = (w.b - w.a) / len, n(-d[1], d[0]);
		const Eigen::Vector2d off = 0.5 * w.thickness * n;
		addVerticalFace(w.a + off, w.b + off, 0, H, surfaceImage(w.front, len, H));
		if (w.hasBack)
			addVerticalFace(w.b - off, w.a - off, 0, H, surfaceImage(w.back, len, H));
		else
			addPlainVerticalFace(w.b - off, w.a - off, 0, H);
		addPlainVerticalFace(w.a - off, w.a + off, 0, H);  // end caps
		addPlainVerticalFace(w.b + off, w.b - off, 0, H);
	}
	for (const Box& b : plan.boxes)
	{
		// The photograph's chosen region is wrapped around the box's sides.
		const auto c = footprint(b);
		const double perimeter = 2 * (b.sizeX + b.sizeY);
		const cv::Mat wrap = surfaceImage(b.texture, perimeter, b.height);
		double start = 0;
		for (size_t i = 0; i < 4; i++)
		{
			const double len = (c[(i + 1) % 4] - c[i]).norm();
			const int x0 = static_cast<int>(std::round(start / perimeter * wrap.cols));
			const int x1 = std::max(x0 + 1, static_cast<int>(std::round((start + len) / perimeter * wrap.cols)));
			start += len;
			addVerticalFace(c[i], c[(i + 1) % 4], 0, b.height, wrap.colRange(x0, std::min(x1, wrap.cols)).clone());
		}
		auto top = mrpt::opengl::CTexturedPlane::Create(
			-b.sizeX / 2, b.sizeX / 2, -b.sizeY / 2, b.sizeY / 2);
		top->assignImage(toCImage(surfaceImage(b.texture, b.sizeX, b.sizeY, 0.0)));
		top->setPose(mrpt::poses::CPose3D(b.centre[0], b.centre[1], b.height, b.yaw, 0, 0));
		m_scene->insert(top);
	}
	for (const Picture& q : plan.pictures)
	{
		const Eigen::Vector2d d = (q.b - q.a).normalized(), n(-d[1], d[0]);
		addVerticalFace(q.a + 0.02 * n, q.b + 0.02 * n, q.z0, q.z1,
			surfaceImage(q.texture, (q.b - q.a).norm(), q.z1 - q.z0));
	}
	for (const Door& door : plan.doors)
	{
		const Eigen::Vector2d d = (door.b - door.a).normalized(), n(-d[1], d[0]);
		const double len = (door.b - door.a).norm(), h = std::min(door.height, H);
		addVerticalFace(door.a + 0.02 * n, door.b + 0.02 * n, 0, h, surfaceImage(door.texture, len, h, 0.0));
		addVerticalFace(door.b - 0.02 * n, door.a - 0.02 * n, 0, h, surfaceImage(door.texture, len, h, 1.0));
	}

	const auto [lo, hi] = plan.bounds();
	auto floor = mrpt::opengl::CTexturedPlane::Create(lo[0], hi[0], lo[1], hi[1]);
	if (plan.hasFloorTexture)
		floor->assignImage(toCImage(surfaceImage(plan.floor, hi[0] - lo[0], hi[1] - lo[1])));
	else
		floor->setColor_u8(150, 140, 125);
	m_scene->insert(floor);
	auto ceiling = mrpt::opengl::CTexturedPlane::Create(lo[0], hi[0], lo[1], hi[1]);
	ceiling->setColor_u8(235, 235, 228);
	ceiling->setLocation(0, 0, H);
	m_scene->insert(ceiling);

	for (size_t i = 0; i < peopleCount; i++)
	{
		auto person = mrpt::opengl::CSetOfObjects::Create();
		auto body = mrpt::opengl::CCylinder::Create(kPersonRadius, kPersonRadius * 0.8, kPersonHeight - 0.25);
		const uint8_t shade = static_cast<uint8_t>(60 + 50 * (i % 3));
		body->setColor_u8(shade, static_cast<uint8_t>(shade / 2 + 20), static_cast<uint8_t>(140 - shade / 3));
		person->insert(body);
		auto head = mrpt::opengl::CSphere::Create(0.12f);
		head->setColor_u8(220, 180, 150);
		head->setLocation(0, 0, kPersonHeight - 0.12);
		person->insert(head);
		person->setVisibility(false);
		m_scene->insert(person);
		m_people.push_back(person);
	}
}

void WorldScene::placePerson(size_t i, bool visible, const Eigen::Vector2d& p)
{
	m_people.at(i)->setVisibility(visible);
	m_people.at(i)->setLocation(p[0], p[1], 0);
}

const cv::Mat& WorldScene::photo(const std::string& file)
{
	auto it = m_photos.find(file);
	if (it != m_photos.end()) return it->second;
	cv::Mat img = cv::imread(file, cv::IMREAD_COLOR);
	if (img.empty() || img.cols < 16 || img.rows < 16)
		throw InputError("texture '" + file + "' is not a readable image (or smaller than 16x16)");
	return m_photos.emplace(file, img).first->second;
}

cv::Mat WorldScene::surfaceImage(const TextureRef& t, double width, double height, double along)
{
	const cv::Mat& img = photo(t.file);
	const double rx0 = t.u0 * img.cols, rx1 = t.u1 * img.cols;
	const double ry0 = t.v0 * img.rows, ry1 = t.v1 * img.rows;
	const double rw = rx1 - rx0, rh = ry1 - ry0, aspect = width / height;
	double cw = rw, ch = rw / aspect;
	if (ch > rh) ch = rh, cw = rh * aspect;
	const double x0 = rx0 + along * (rw - cw), y0 = ry0 + 0.5 * (rh - ch);
	cv::Rect roi(
		static_cast<int>(x0), static_cast<int>(y0), std::max(1, static_cast<int>(cw)),
		std::max(1, static_cast<int>(ch)));
	roi &= cv::Rect(0, 0, img.cols, img.rows);
	cv::Mat crop = img(roi);
	const double scale = std::min(1.0, m_maxSide / static_cast<double>(std::max(crop.cols, crop.rows)));
	cv::Mat out;
	if (scale < 1)
		cv::resize(crop, out, cv::Size(), scale, scale, cv::INTER_AREA);
	else
		out = crop.clone();
	cv::flip(out, out, t.mirrored ? -1 : 0);  // image row 0 is the plane's bottom edge
	return out;
}

void WorldScene::addVerticalFace(
	const Eigen::Vector2d& a, const Eigen::Vector2d& b, double z0, double z1, const cv::Mat& image)
{
	// The plane's local x runs from b to a and its normal (local z after
	// the roll) points to the left of a -> b, so seen from that side the
	// photograph is not mirrored.
	const double len = (a - b).norm();
	auto plane = mrpt::opengl::CTexturedPlane::Create(0, len, z0, z1);
	plane->assignImage(toCImage(image));
	const double yaw = std::atan2(a[1] - b[1], a[0] - b[0]);
	plane->setPose(mrpt::poses::CPose3D(b[0], b[1], 0, yaw, 0, M_PI / 2));
	m_scene->insert(plane);
}

void WorldScene::addPlainVerticalFace(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double z0, double z1)
{
	const double len = (a - b).norm();
	if (len < 1e-6) return;
	auto plane = mrpt::opengl::CTexturedPlane::Create(0, len, z0, z1);
	plane->setColor_u8(225, 222, 215);
	const double yaw = std::atan2(a[1] - b[1], a[0] - b[0]);
	plane->setPose(mrpt::poses::CPose3D(b[0], b[1], 0, yaw, 0, M_PI / 2));
	m_scene->insert(plane);
}
}  // namespace vslam::world

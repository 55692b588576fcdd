/** The rendered camera's geometry: a marker at a known 3-D point appears
 * where the calibration (pinhole + distortion) projects it. */
#include <gtest/gtest.h>
#include <libvslam/sim/CameraRenderer.h>
#include <mrpt/img/CImage.h>
#include <mrpt/opengl/CTexturedPlane.h>
#include <opencv2/calib3d.hpp>

using namespace vslam;

namespace
{
/** Markers: 8 cm squares facing the camera (parallel to its image plane,
 * so the centre of the square projects to the centre of its image), each
 * carrying a smooth red spot on white: the intensity-weighted centroid of
 * the spot locates it to a small fraction of a pixel. */
mrpt::opengl::COpenGLScene::Ptr markerScene(
	const std::vector<mrpt::math::TPoint3D>& points, const mrpt::poses::CPose3D& camera)
{
	cv::Mat spot(64, 64, CV_8UC3);
	for (int r = 0; r < 64; r++)
		for (int c = 0; c < 64; c++)
		{
			const double d2 = (r - 31.5) * (r - 31.5) + (c - 31.5) * (c - 31.5);
			const auto other = static_cast<uint8_t>(255 - 255 * std::exp(-d2 / (2 * 10.0 * 10.0)));
			spot.at<cv::Vec3b>(r, c) = {other, other, 255};
		}
	auto scene = mrpt::opengl::COpenGLScene::Create();
	for (const auto& p : points)
	{
		auto plane = mrpt::opengl::CTexturedPlane::Create(-0.04, 0.04, -0.04, 0.04);
		plane->assignImage(mrpt::img::CImage(spot, mrpt::img::DEEP_COPY));
		mrpt::poses::CPose3D pose = camera;
		pose.x(p.x), pose.y(p.y), pose.z(p.z);
		plane->setPose(pose);
		scene->insert(plane);
	}
	return scene;
}

/** Redness-weighted centroid in a window around `near`. */
cv::Point2d redCentroid(const cv::Mat& bgr, const cv::Point2d& near, int radius = 14)
{
	double su = 0, sv = 0, n = 0;
	for (int v = std::max(0, int(near.y) - radius); v < std::min(bgr.rows, int(near.y) + radius); v++)
		for (int u = std::max(0, int(near.x) - radius); u < std::min(bgr.cols, int(near.x) + radius); u++)
		{
			const auto& px = bgr.at<cv::Vec3b>(v, u);
			const double w = std::max(0, px[2] - px[1] - 10);
			su += w * u, sv += w * v, n += w;
		}
	return n > 0 ? cv::Point2d(su / n, sv / n) : cv::Point2d(-1, -1);
}

cv::Point2d project(const mrpt::img::TCamera& cam, const mrpt::poses::CPose3D& cameraPose, const mrpt::math::TPoint3D& p)
{
	const auto pc = cameraPose.inverseComposePoint(p);
	const std::vector<cv::Point3d> obj{{pc.x, pc.y, pc.z}};
	std::vector<cv::Point2d> img;
	const cv::Matx33d K(cam.fx(), 0, cam.cx(), 0, cam.fy(), cam.cy(), 0, 0, 1);
	const std::vector<double> D{cam.k1(), cam.k2(), cam.p1(), cam.p2(), cam.k3()};
	cv::projectPoints(obj, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, D, img);
	return img[0];
}

void expectMarkersWhereProjected(const mrpt::img::TCamera& cam)
{
	// A robot at (1, 2) facing 30 deg, the camera mounted ahead, pitched
	// down 5 deg and rolled 2 deg; markers at 1.5-3 m all over the view.
	const mrpt::poses::CPose3D mount =
		mrpt::poses::CPose3D(0.1, 0.05, 0.4, 0.0, 5 * M_PI / 180, 2 * M_PI / 180) +
		mrpt::poses::CPose3D(0, 0, 0, -M_PI / 2, 0, -M_PI / 2);
	const mrpt::poses::CPose3D camera = mrpt::poses::CPose3D(1, 2, 0, 30 * M_PI / 180, 0, 0) + mount;
	std::vector<mrpt::math::TPoint3D> points;
	for (double u : {0.1, 0.5, 0.9})
		for (double v : {0.15, 0.5, 0.85})
		{
			// The ray through pixel (u W, v H) of the undistorted camera, at 2 m.
			const double depth = 1.5 + u + v;
			const double xn = (u * cam.ncols - cam.cx()) / cam.fx(), yn = (v * cam.nrows - cam.cy()) / cam.fy();
			points.push_back(camera.composePoint(mrpt::math::TPoint3D(xn * depth, yn * depth, depth)));
		}
	CameraRenderer renderer(cam);
	const cv::Mat img = renderer.render(*markerScene(points, camera), camera);
	ASSERT_EQ(img.cols, int(cam.ncols));
	ASSERT_EQ(img.rows, int(cam.nrows));
	for (const auto& p : points)
	{
		const cv::Point2d expected = project(cam, camera, p);
		const cv::Point2d found = redCentroid(img, expected);
		EXPECT_NEAR(found.x, expected.x, 0.15) << "marker at " << p;
		EXPECT_NEAR(found.y, expected.y, 0.15) << "marker at " << p;
	}
}
}  // namespace

TEST(CameraRenderer, MarkersAppearWhereThePinholeModelProjectsThem)
{
	mrpt::img::TCamera cam;
	cam.ncols = 320, cam.nrows = 240;
	cam.setIntrinsicParamsFromValues(250, 240, 158.3, 121.7);
	cam.dist.fill(0);
	expectMarkersWhereProjected(cam);
	cam.ncols = 322;  // not a multiple of 4: MRPT's renderer needs padding
	expectMarkersWhereProjected(cam);
}

TEST(CameraRenderer, MarkersAppearWhereTheDistortedModelProjectsThem)
{
	mrpt::img::TCamera cam;
	cam.ncols = 640, cam.nrows = 480;
	cam.setIntrinsicParamsFromValues(420, 420, 322, 236);
	cam.dist.fill(0);
	cam.dist[0] = -0.28, cam.dist[1] = 0.08, cam.dist[2] = 0.001, cam.dist[3] = -0.0005;
	expectMarkersWhereProjected(cam);
}

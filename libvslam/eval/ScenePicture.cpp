#include <libvslam/core/InputError.h>
#include <libvslam/core/OutputError.h>
#include <libvslam/eval/ScenePicture.h>
#include <mrpt/img/CImage.h>
#include <mrpt/opengl/CFBORender.h>
#include <mrpt/opengl/COpenGLScene.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace vslam
{
void writeScenePicture(const std::string& sceneFile, const std::string& pngFile, int width, int height)
{
	mrpt::opengl::COpenGLScene scene;
	if (!scene.loadFromFile(sceneFile)) throw InputError("cannot read the 3-D scene '" + sceneFile + "'");
	scene.getViewport()->setCustomBackgroundColor({1.0f, 1.0f, 1.0f});
	const auto box = scene.getBoundingBox();
	const double extent = std::max({box.max.x - box.min.x, box.max.y - box.min.y, 1.0});
	// MRPT 2.5's CFBORender reads rows 4-byte aligned: keep the width a multiple of 4.
	const int paddedWidth = width + (4 - width % 4) % 4;
	mrpt::opengl::CFBORender renderer(mrpt::opengl::CFBORender::Parameters(paddedWidth, height));
	auto& camera = renderer.getCamera(scene);
	camera.setPointingAt(0.5 * (box.min.x + box.max.x), 0.5 * (box.min.y + box.max.y), 0);
	camera.setAzimuthDegrees(-90);  // x to the right, y up the image, as in the 2-D figures
	camera.setElevationDegrees(70);
	camera.setZoomDistance(1.3 * extent);
	mrpt::img::CImage image;
	renderer.render_RGB(scene, image);
	cv::Mat bgr = image.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	if (bgr.channels() == 1) cv::cvtColor(bgr, bgr, cv::COLOR_GRAY2BGR);
	if (!cv::imwrite(pngFile, bgr.colRange(0, width)))
		throw OutputError("cannot write the image '" + pngFile + "'");
}
}  // namespace vslam

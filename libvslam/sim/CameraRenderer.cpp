#include <libvslam/core/InputError.h>
#include <libvslam/sim/CameraRenderer.h>
#include <mrpt/img/CImage.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace vslam
{
namespace
{
/** OpenGL samples pixel centres at +0.5; the pinhole model of TCamera puts
 * pixel (u, v)'s centre at (u, v). Shifting the principal point given to
 * the renderer by half a pixel makes both agree (checked by the geometry
 * test, which finds rendered markers where TCamera projects them). */
constexpr double kPixelCentreShift = 0.5;
}  // namespace

#ifdef __SANITIZE_ADDRESS__
/** Mesa's software rasterizer (and the LLVM it compiles shaders with) keeps
 * some allocations until the process exits; LeakSanitizer would fail every
 * program that renders. Only leaks whose stack is inside those libraries
 * are ignored: the renderer's own allocations are still checked. */
extern "C" const char* __lsan_default_suppressions()
{
	return "leak:swrast_dri.so\nleak:libLLVM\nleak:libgallium\nleak:libGLX_mesa\nleak:libEGL_mesa\n";
}
/** Without the list of suppressions used at every exit (LSAN_OPTIONS still
 * overrides this). */
extern "C" const char* __lsan_default_options()
{
	return "print_suppressions=0";
}
#endif

CameraRenderer::CameraRenderer(const mrpt::img::TCamera& camera) : m_camera(camera)
{
	const int W = static_cast<int>(camera.ncols), H = static_cast<int>(camera.nrows);
	if (W < 16 || H < 16 || W > 4096 || H > 4096)
		throw InputError("camera image size " + std::to_string(W) + "x" + std::to_string(H) + " outside 16..4096");
	for (size_t i = 0; i < camera.dist.size(); i++) m_distorted = m_distorted || camera.dist[i] != 0;
	m_idealCamera = camera;
	m_idealCamera.dist.fill(0);
	if (m_distorted)
	{
		// Where every distorted pixel's ray falls in an ideal image, and the
		// ideal image size (with margins) that contains them all.
		std::vector<cv::Point2f> pixels;
		pixels.reserve(static_cast<size_t>(W) * H);
		for (int v = 0; v < H; v++)
			for (int u = 0; u < W; u++) pixels.emplace_back(static_cast<float>(u), static_cast<float>(v));
		const cv::Matx33d K(camera.fx(), 0, camera.cx(), 0, camera.fy(), camera.cy(), 0, 0, 1);
		const std::vector<double> D = {camera.k1(), camera.k2(), camera.p1(), camera.p2(), camera.k3()};
		std::vector<cv::Point2f> normalized;
		cv::undistortPoints(pixels, normalized, K, D);
		double minU = 0, maxU = W - 1, minV = 0, maxV = H - 1;
		for (const auto& n : normalized)
		{
			const double u = camera.fx() * n.x + camera.cx(), v = camera.fy() * n.y + camera.cy();
			if (!std::isfinite(u) || !std::isfinite(v)) throw InputError("camera distortion cannot be inverted");
			minU = std::min(minU, u), maxU = std::max(maxU, u), minV = std::min(minV, v), maxV = std::max(maxV, v);
		}
		const int left = static_cast<int>(std::ceil(-minU)) + 2, top = static_cast<int>(std::ceil(-minV)) + 2;
		int right = static_cast<int>(std::ceil(maxU - (W - 1))) + 2;
		// MRPT 2.5's CFBORender reads pixels with OpenGL's default 4-byte row
		// alignment into a packed buffer: widths that are not a multiple of
		// 4 overrun it. Pad the margin instead.
		right += (4 - (W + left + right) % 4) % 4;
		const int bottom = static_cast<int>(std::ceil(maxV - (H - 1))) + 2;
		if (left + right > 2 * W || top + bottom > 2 * H)
			throw InputError("camera distortion too strong to render (field of view over twice the undistorted one)");
		m_idealCamera.ncols = static_cast<uint32_t>(W + left + right);
		m_idealCamera.nrows = static_cast<uint32_t>(H + top + bottom);
		m_idealCamera.cx(camera.cx() + left);
		m_idealCamera.cy(camera.cy() + top);
		m_mapX.create(H, W, CV_32F);
		m_mapY.create(H, W, CV_32F);
		for (int v = 0; v < H; v++)
			for (int u = 0; u < W; u++)
			{
				const auto& n = normalized[static_cast<size_t>(v) * W + u];
				m_mapX.at<float>(v, u) = static_cast<float>(m_idealCamera.fx() * n.x + m_idealCamera.cx());
				m_mapY.at<float>(v, u) = static_cast<float>(m_idealCamera.fy() * n.y + m_idealCamera.cy());
			}
	}
	else
	{
		// See above: pad to a multiple of 4 columns, cropped after rendering.
		m_idealCamera.ncols = static_cast<uint32_t>(W + (4 - W % 4) % 4);
	}
	m_renderer = std::make_unique<mrpt::opengl::CFBORender>(
		mrpt::opengl::CFBORender::Parameters(m_idealCamera.ncols, m_idealCamera.nrows));
}

cv::Mat CameraRenderer::render(const mrpt::opengl::COpenGLScene& scene, const mrpt::poses::CPose3D& cameraPose)
{
	mrpt::img::TCamera gl = m_idealCamera;
	gl.cx(gl.cx() + kPixelCentreShift);
	gl.cy(gl.cy() + kPixelCentreShift);
	auto& cam = m_renderer->getCamera(scene);
	cam.set6DOFMode(true);
	cam.setProjectiveFromPinhole(gl);
	cam.setPose(cameraPose);
	mrpt::img::CImage rendered;
	m_renderer->render_RGB(scene, rendered);
	cv::Mat ideal = rendered.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	if (ideal.channels() == 1) cv::cvtColor(ideal, ideal, cv::COLOR_GRAY2BGR);
	if (!m_distorted) return ideal.colRange(0, static_cast<int>(m_camera.ncols)).clone();
	cv::Mat out;
	cv::remap(ideal, out, m_mapX, m_mapY, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
	return out;
}

}  // namespace vslam

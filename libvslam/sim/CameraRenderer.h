#pragma once
/** \file CameraRenderer.h
 * Renders what a calibrated camera sees of a 3-D scene, headless, with
 * MRPT's offscreen renderer (mrpt::opengl::CFBORender through EGL):
 * an ideal pinhole image with the camera's focal lengths and principal
 * point, then the lens distortion of the calibration (the radial-tangential
 * model of mrpt::img::TCamera) applied by resampling. What the sensor makes
 * of it is CameraImaging's.
 */
#include <mrpt/img/TCamera.h>
#include <mrpt/opengl/CFBORender.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/poses/CPose3D.h>
#include <opencv2/core.hpp>

#include <memory>

namespace vslam
{
class CameraRenderer
{
   public:
	explicit CameraRenderer(const mrpt::img::TCamera& camera);

	/** The 8-bit BGR image seen from `cameraPose` (MRPT camera axes:
	 * z forward, x right, y down). */
	cv::Mat render(const mrpt::opengl::COpenGLScene& scene, const mrpt::poses::CPose3D& cameraPose);

	const mrpt::img::TCamera& camera() const { return m_camera; }

   private:
	mrpt::img::TCamera m_camera;
	bool m_distorted = false;
	mrpt::img::TCamera m_idealCamera;  //!< of the rendered (undistorted) image
	std::unique_ptr<mrpt::opengl::CFBORender> m_renderer;
	cv::Mat m_mapX, m_mapY;  //!< distorted pixel -> ideal image position
};
}  // namespace vslam

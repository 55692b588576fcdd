#pragma once
/** \file PinholeCamera.h
 * The ideal pinhole camera the front-end works in. Keypoints are undistorted
 * once, right after detection, with the observation's own calibration
 * (mrpt::img::TCamera: intrinsics and distortion), so everything after
 * that (triangulation, PnP) uses K without distortion.
 */
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/img/TCamera.h>
#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace vslam
{
struct PinholeCamera
{
	double fx = 0, fy = 0, cx = 0, cy = 0;

	cv::Matx33d K() const { return {fx, 0, cx, 0, fy, cy, 0, 0, 1}; }
	/** Pixel of a point in camera coordinates (z forward, x right, y down). */
	cv::Point2d project(const cv::Point3d& p) const
	{
		return {fx * p.x / p.z + cx, fy * p.y / p.z + cy};
	}
	/** Unit-depth ray of a (undistorted) pixel. */
	cv::Point3d ray(const cv::Point2d& px) const { return {(px.x - cx) / fx, (px.y - cy) / fy, 1.0}; }
};

/** The calibration of one image: its own, or the INI overrides. Throws
 * std::invalid_argument naming `what` if the calibration is unusable (no
 * focal length, principal point outside the image, image size differing
 * from the calibrated one). */
struct CImageCalibration
{
	/** INI section [vslam_camera]: a calibration that replaces the
	 * images' own, for data sets without one (fx = 0: the images'). */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		static constexpr const char* kSection = "vslam_camera";
		double fx = 0, fy = 0, cx = 0, cy = 0;

		void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
		void saveToConfigFile(mrpt::config::CConfigFileBase& target, const std::string& section) const override;
	};

	PinholeCamera camera;
	cv::Mat distortion;  //!< OpenCV order k1 k2 p1 p2 k3, CV_64F, may be all zero

	static CImageCalibration from(
		const mrpt::img::TCamera& params, int imageWidth, int imageHeight,
		const TOptions& overrides, const std::string& what);

	/** Removes lens distortion from pixel positions (no-op without it). */
	std::vector<cv::Point2f> undistort(const std::vector<cv::Point2f>& pixels) const;
};
}  // namespace vslam

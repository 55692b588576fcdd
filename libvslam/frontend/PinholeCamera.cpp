#include <libvslam/config/ConfigError.h>
#include <libvslam/config/StrictRead.h>
#include <libvslam/frontend/PinholeCamera.h>
#include <opencv2/calib3d.hpp>

#include <cmath>
#include <stdexcept>

using namespace vslam;

void CImageCalibration::TOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace config;
	fx = readDouble(c, s, "fx", fx, Range::nonNegative());
	fy = readDouble(c, s, "fy", fy, Range::nonNegative());
	cx = readDouble(c, s, "cx", cx, Range::nonNegative());
	cy = readDouble(c, s, "cy", cy, Range::nonNegative());
	if ((fx > 0) != (fy > 0)) throw ConfigError("[" + s + "] fx and fy must be given together");
}

void CImageCalibration::TOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "fx", fx, 30, 10, "Focal length override [px] (0: from each image)");
	c.write(s, "fy", fy, 30, 10, "Focal length override [px] (0: from each image)");
	c.write(s, "cx", cx, 30, 10, "Principal point override [px] (with fx, fy)");
	c.write(s, "cy", cy, 30, 10, "Principal point override [px] (with fx, fy)");
}

CImageCalibration CImageCalibration::from(
	const mrpt::img::TCamera& p, int width, int height, const TOptions& o,
	const std::string& what)
{
	CImageCalibration c;
	const bool overridden = o.fx > 0;
	c.camera = overridden ? PinholeCamera{o.fx, o.fy, o.cx, o.cy}
						  : PinholeCamera{p.fx(), p.fy(), p.cx(), p.cy()};
	const auto bad = [&](const std::string& why) {
		return std::invalid_argument(what + ": unusable camera calibration: " + why);
	};
	if (!(std::isfinite(c.camera.fx) && std::isfinite(c.camera.fy) && c.camera.fx > 0 && c.camera.fy > 0))
		throw bad("no focal length (set [vslam_camera] fx, fy, cx, cy if the data has none)");
	if (!overridden && p.ncols > 0 && p.nrows > 0 &&
		(static_cast<int>(p.ncols) != width || static_cast<int>(p.nrows) != height))
		throw bad("calibrated for " + std::to_string(p.ncols) + "x" + std::to_string(p.nrows) +
			" images, this one is " + std::to_string(width) + "x" + std::to_string(height));
	if (!(c.camera.cx >= 0 && c.camera.cx < width && c.camera.cy >= 0 && c.camera.cy < height))
		throw bad("principal point (" + std::to_string(c.camera.cx) + ", " + std::to_string(c.camera.cy) +
			") outside the " + std::to_string(width) + "x" + std::to_string(height) + " image");
	c.distortion = cv::Mat::zeros(1, 5, CV_64F);
	if (!overridden)
	{
		const double d[5] = {p.k1(), p.k2(), p.p1(), p.p2(), p.k3()};
		for (int i = 0; i < 5; i++)
		{
			if (!std::isfinite(d[i])) throw bad("distortion coefficient is not finite");
			c.distortion.at<double>(i) = d[i];
		}
	}
	return c;
}

std::vector<cv::Point2f> CImageCalibration::undistort(const std::vector<cv::Point2f>& pixels) const
{
	if (pixels.empty() || cv::countNonZero(distortion) == 0) return pixels;
	std::vector<cv::Point2f> out;
	const cv::Mat K(camera.K());
	cv::undistortPoints(pixels, out, K, distortion, cv::noArray(), K);
	return out;
}

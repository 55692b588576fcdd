#include <libvslam/core/InputError.h>
#include <libvslam/world/AssetArchive.h>
#include <libvslam/world/SurfaceTextures.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>

namespace vslam::world
{
SurfaceTextures::SurfaceTextures(const FloorPlan& plan, int maxSide) : m_plan(plan), m_maxSide(maxSide) {}

const cv::Mat& SurfaceTextures::photo(const std::string& file)
{
	auto it = m_photos.find(file);
	if (it != m_photos.end()) return it->second;
	const std::optional<AssetLocation> at = locateAsset(file);
	if (!at) throw InputError("texture '" + file + "' does not exist");
	cv::Mat img = readAssetImage(*at);
	if (img.cols < 16 || img.rows < 16) throw InputError("texture '" + file + "' is smaller than 16x16");
	return m_photos.emplace(file, img).first->second;
}

const cv::Mat& SurfaceTextures::tile(int index)
{
	auto it = m_tiles.find(index);
	if (it != m_tiles.end()) return it->second;
	const Material& m = m_plan.materials.at(static_cast<size_t>(index));
	cv::Mat f;
	photo(m.file).convertTo(f, CV_32FC3);
	const cv::Scalar mean = cv::mean(f);
	// Contrast around the mean, then the paint's colour (BGR order).
	f = (f - mean) * m.contrast + mean;
	cv::multiply(f, cv::Scalar(m.tint[2], m.tint[1], m.tint[0]), f);
	cv::Mat out;
	f.convertTo(out, CV_8UC3);
	const double scale = std::min(1.0, m_maxSide / static_cast<double>(std::max(out.cols, out.rows)));
	if (scale < 1) cv::resize(out, out, cv::Size(), scale, scale, cv::INTER_AREA);
	cv::flip(out, out, 0);
	return m_tiles.emplace(index, out).first->second;
}

SurfaceImage SurfaceTextures::surface(const TextureRef& t, double width, double height, double along)
{
	SurfaceImage s;
	if (t.material >= 0)
	{
		const Material& m = m_plan.materials.at(static_cast<size_t>(t.material));
		s.image = tile(t.material);
		s.tiled = true, s.tileWidth = m.tileWidth, s.tileHeight = m.tileHeight;
		return s;
	}
	const cv::Mat& img = photo(t.file);
	const double rx0 = t.u0 * img.cols, rx1 = t.u1 * img.cols;
	const double ry0 = t.v0 * img.rows, ry1 = t.v1 * img.rows;
	const double rw = rx1 - rx0, rh = ry1 - ry0, aspect = width / height;
	double cw = rw, ch = rw / aspect;
	if (ch > rh) ch = rh, cw = rh * aspect;
	const double x0 = rx0 + along * (rw - cw), y0 = ry0 + 0.5 * (rh - ch);
	cv::Rect roi(static_cast<int>(x0), static_cast<int>(y0), std::max(1, static_cast<int>(cw)),
		std::max(1, static_cast<int>(ch)));
	roi &= cv::Rect(0, 0, img.cols, img.rows);
	const cv::Mat crop = img(roi);
	const double scale = std::min(1.0, m_maxSide / static_cast<double>(std::max(crop.cols, crop.rows)));
	if (scale < 1)
		cv::resize(crop, s.image, cv::Size(), scale, scale, cv::INTER_AREA);
	else
		s.image = crop.clone();
	cv::flip(s.image, s.image, t.mirrored ? -1 : 0);
	return s;
}

cv::Scalar SurfaceTextures::meanColour(const TextureRef& t)
{
	return cv::mean(t.material >= 0 ? tile(t.material) : photo(t.file));
}
}  // namespace vslam::world

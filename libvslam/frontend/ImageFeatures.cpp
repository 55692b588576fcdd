#include <libvslam/config/StrictRead.h>
#include <libvslam/frontend/ImageFeatures.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

using namespace vslam;

namespace
{
/** Lowe's edge threshold (the ratio of principal curvatures): OpenCV's default. */
constexpr double kSiftEdgeThreshold = 10;
/** The narrowest image SIFT is given: a few octaves, however small the camera. */
constexpr int kMinSiftCols = 32;
}  // namespace

void CFeatureExtractor::TOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace config;
	sift_features = readCount(c, s, "sift_features", sift_features, 0, 100000);
	sift_contrast_threshold = readDouble(c, s, "sift_contrast_threshold", sift_contrast_threshold, Range::closed(0, 1));
	sift_max_cols = readCount(c, s, "sift_max_cols", sift_max_cols, 0, 100000);
	if (sift_max_cols != 0 && sift_max_cols < kMinSiftCols)
		throw ConfigError("[" + s + "] sift_max_cols must be 0 or at least " + std::to_string(kMinSiftCols));
	sift_denoise_sigma = readDouble(c, s, "sift_denoise_sigma", sift_denoise_sigma, Range::closed(0, 5));
	match_ratio = readDouble(c, s, "match_ratio", match_ratio, {0, 1, false, true});
}

void CFeatureExtractor::TOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "sift_features", sift_features, 30, 10, "Strongest SIFT features kept per image (0: all)");
	c.write(s, "sift_contrast_threshold", sift_contrast_threshold, 30, 10, "SIFT contrast threshold");
	c.write(s, "sift_denoise_sigma", sift_denoise_sigma, 30, 10,
		"Gaussian blur of the image before SIFT against pixel noise [px std] (0: none)");
	c.write(s, "sift_max_cols", sift_max_cols, 30, 10,
		"Images wider than this [px] are scaled down to it before SIFT, which doubles its input: the finest features' detail and SIFT's time (0: as they are; else at least 32)");
	c.write(s, "match_ratio", match_ratio, 30, 10,
		"Ratio test of every feature match (creation, candidates, recognition, heading change): best / second-best distance below this");
}

CFeatureExtractor::CFeatureExtractor(const TOptions& o)
	: m_sift(cv::SIFT::create(o.sift_features, 3, o.sift_contrast_threshold, kSiftEdgeThreshold)),
	  m_maxCols(o.sift_max_cols),
	  m_denoiseSigma(o.sift_denoise_sigma)
{
}

namespace
{
/** OpenCV (4.6) doubles the image with a pixel-centre-aligned resize, so a
 * pixel j of the doubled image lies at (j + 0.5) / 2 - 0.5 of the input,
 * but it reports its keypoints at j / 2: a quarter pixel too far right and
 * down. */
constexpr float kOpenCvUpsamplingShift = 0.25f;
}  // namespace

std::vector<cv::Point2f> CFeatureExtractor::detect(const cv::Mat& grey, cv::Mat& descriptors) const
{
	cv::Mat input = grey;
	if (m_maxCols > 0 && grey.cols > m_maxCols)
	{
		const double scale = static_cast<double>(m_maxCols) / grey.cols;
		const int rows = std::max(1, static_cast<int>(std::lround(grey.rows * scale)));
		cv::resize(grey, input, cv::Size(m_maxCols, rows), 0, 0, cv::INTER_AREA);
	}
	std::vector<cv::KeyPoint> keypoints;
	m_sift->detectAndCompute(input, cv::noArray(), keypoints, descriptors);
	std::vector<cv::Point2f> pixels;
	pixels.reserve(keypoints.size());
	for (const auto& k : keypoints)
		pixels.emplace_back(k.pt.x - kOpenCvUpsamplingShift, k.pt.y - kOpenCvUpsamplingShift);
	if (input.cols == grey.cols) return pixels;
	// Each pixel i of the scaled image averages the input over
	// [i * s, (i + 1) * s), its centre at (i + 0.5) * s - 0.5.
	const float sx = static_cast<float>(grey.cols) / input.cols, sy = static_cast<float>(grey.rows) / input.rows;
	for (auto& p : pixels) p = {(p.x + 0.5f) * sx - 0.5f, (p.y + 0.5f) * sy - 0.5f};
	return pixels;
}

ImageFeatures CFeatureExtractor::extract(const cv::Mat& image, const CImageCalibration& calib) const
{
	cv::Mat grey;
	if (image.channels() == 1)
		grey = image;
	else if (image.channels() == 3)
		cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
	else
		cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
	if (grey.depth() != CV_8U) grey.convertTo(grey, CV_8U);
	if (m_denoiseSigma > 0)
	{
		cv::Mat blurred;  // never in place: grey may share the caller's pixels
		cv::GaussianBlur(grey, blurred, cv::Size(), m_denoiseSigma);
		grey = blurred;
	}

	ImageFeatures f;
	f.camera = calib.camera;
	f.pixels = calib.undistort(detect(grey, f.descriptors));
	if (f.descriptors.empty()) f.descriptors = cv::Mat(0, 128, CV_32F);
	return f;
}

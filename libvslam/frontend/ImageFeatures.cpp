#include <libvslam/config/StrictRead.h>
#include <libvslam/frontend/ImageFeatures.h>
#include <opencv2/imgproc.hpp>

using namespace vslam;

namespace
{
/** Lowe's edge threshold (the ratio of principal curvatures): OpenCV's default. */
constexpr double kSiftEdgeThreshold = 10;
}  // namespace

void CFeatureExtractor::TOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace config;
	sift_features = readCount(c, s, "sift_features", sift_features, 0, 100000);
	sift_contrast_threshold = readDouble(c, s, "sift_contrast_threshold", sift_contrast_threshold, Range::closed(0, 1));
	sift_upsample = readBool(c, s, "sift_upsample", sift_upsample);
	sift_denoise_sigma = readDouble(c, s, "sift_denoise_sigma", sift_denoise_sigma, Range::closed(0, 5));
	match_ratio = readDouble(c, s, "match_ratio", match_ratio, {0, 1, false, true});
}

void CFeatureExtractor::TOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "sift_features", sift_features, 30, 10, "Strongest SIFT features kept per image (0: all)");
	c.write(s, "sift_contrast_threshold", sift_contrast_threshold, 30, 10, "SIFT contrast threshold");
	c.write(s, "sift_denoise_sigma", sift_denoise_sigma, 30, 10,
		"Gaussian blur of the image before SIFT against pixel noise [px std] (0: none)");
	c.write(s, "sift_upsample", sift_upsample, 30, 10,
		"SIFT's first octave on the image doubled (true: finest features) or as it is (false: about 3x faster, less accurate)");
	c.write(s, "match_ratio", match_ratio, 30, 10,
		"Ratio test of every feature match (creation, candidates, recognition, heading change): best / second-best distance below this");
}

CFeatureExtractor::CFeatureExtractor(const TOptions& o)
	: m_sift(cv::SIFT::create(o.sift_features, 3, o.sift_contrast_threshold, kSiftEdgeThreshold)),
	  m_upsample(o.sift_upsample),
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
	std::vector<cv::KeyPoint> keypoints;
	std::vector<cv::Point2f> pixels;
	if (m_upsample)
	{
		m_sift->detectAndCompute(grey, cv::noArray(), keypoints, descriptors);
		for (const auto& k : keypoints)
			pixels.emplace_back(k.pt.x - kOpenCvUpsamplingShift, k.pt.y - kOpenCvUpsamplingShift);
		return pixels;
	}
	// SIFT's first octave on the image as it is: give OpenCV the image halved
	// (area averaging), which it doubles back. Each pixel i of the half image
	// averages the input over [i * s, (i + 1) * s), its centre at
	// (i + 0.5) * s - 0.5.
	if (grey.cols < 2 || grey.rows < 2) return pixels;
	cv::Mat half;
	cv::resize(grey, half, cv::Size(grey.cols / 2, grey.rows / 2), 0, 0, cv::INTER_AREA);
	m_sift->detectAndCompute(half, cv::noArray(), keypoints, descriptors);
	const float sx = static_cast<float>(grey.cols) / half.cols, sy = static_cast<float>(grey.rows) / half.rows;
	for (const auto& k : keypoints)
	{
		const cv::Point2f inHalf(k.pt.x - kOpenCvUpsamplingShift, k.pt.y - kOpenCvUpsamplingShift);
		pixels.emplace_back((inHalf.x + 0.5f) * sx - 0.5f, (inHalf.y + 0.5f) * sy - 0.5f);
	}
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

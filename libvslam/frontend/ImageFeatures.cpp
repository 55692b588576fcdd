#include <libvslam/frontend/ImageFeatures.h>
#include <libvslam/frontend/TVisualFrontEndOptions.h>
#include <opencv2/imgproc.hpp>

#include <map>

using namespace vslam;

FeatureExtractor::FeatureExtractor(const TVisualFrontEndOptions& o)
	: m_sift(cv::SIFT::create(o.sift_features, 3, o.sift_contrast_threshold, o.sift_edge_threshold))
{
}

ImageFeatures FeatureExtractor::extract(const cv::Mat& image, const ImageCalibration& calib) const
{
	cv::Mat grey;
	if (image.channels() == 1)
		grey = image;
	else if (image.channels() == 3)
		cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
	else
		cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
	if (grey.depth() != CV_8U) grey.convertTo(grey, CV_8U);

	std::vector<cv::KeyPoint> keypoints;
	ImageFeatures f;
	f.camera = calib.camera;
	m_sift->detectAndCompute(grey, cv::noArray(), keypoints, f.descriptors);
	std::vector<cv::Point2f> raw;
	raw.reserve(keypoints.size());
	for (const auto& k : keypoints) raw.push_back(k.pt);
	f.pixels = calib.undistort(raw);
	if (f.descriptors.empty()) f.descriptors = cv::Mat(0, 128, CV_32F);
	return f;
}

std::vector<std::pair<int, int>> vslam::matchDescriptors(
	const cv::Mat& a, const cv::Mat& b, double ratio)
{
	std::vector<std::pair<int, int>> out;
	if (a.rows == 0 || b.rows < 2) return out;
	cv::BFMatcher matcher(cv::NORM_L2);
	std::vector<std::vector<cv::DMatch>> knn;
	matcher.knnMatch(a, b, knn, 2);
	// Keep each b for its best a only.
	std::map<int, std::pair<float, int>> bestForB;
	for (const auto& m : knn)
	{
		if (m.size() < 2 || m[0].distance >= ratio * m[1].distance) continue;
		auto it = bestForB.find(m[0].trainIdx);
		if (it == bestForB.end() || m[0].distance < it->second.first)
			bestForB[m[0].trainIdx] = {m[0].distance, m[0].queryIdx};
	}
	for (const auto& [bi, da] : bestForB) out.emplace_back(da.second, bi);
	return out;
}

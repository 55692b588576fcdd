#pragma once
/** \file ImageFeatures.h
 * SIFT features of one image: undistorted pixel positions and descriptors
 * (one CV_32F row of 128 each). */
#include <libvslam/frontend/PinholeCamera.h>
#include <mrpt/img/CImage.h>
#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>

#include <vector>

namespace vslam
{
struct TVisualFrontEndOptions;

struct ImageFeatures
{
	PinholeCamera camera;
	std::vector<cv::Point2f> pixels;  //!< undistorted
	cv::Mat descriptors;  //!< N x 128, CV_32F
	/** The descriptors in the landmark store's matching space (see
	 * DescriptorCodec); empty: match the descriptors as they are. */
	cv::Mat codes;
	/** The descriptors in the database's search space (CV_32F). */
	cv::Mat searchCodes;

	size_t size() const { return pixels.size(); }
};

/** Detects SIFT features in an image of any size, colour or grey, at
 * their true pixel positions (pixel centres at integer coordinates). */
class FeatureExtractor
{
   public:
	explicit FeatureExtractor(const TVisualFrontEndOptions& options);
	/** Features of `image`; `calibration` undistorts them. */
	ImageFeatures extract(const cv::Mat& image, const ImageCalibration& calibration) const;

   private:
	/** Raw (distorted) pixel positions and descriptors of a grey image. */
	std::vector<cv::Point2f> detect(const cv::Mat& grey, cv::Mat& descriptors) const;

	cv::Ptr<cv::SIFT> m_sift;
	bool m_upsample;
	double m_denoiseSigma;
};
}  // namespace vslam

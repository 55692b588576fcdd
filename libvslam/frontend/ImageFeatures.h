#pragma once
/** \file ImageFeatures.h
 * SIFT features of one image: undistorted pixel positions and descriptors
 * (one CV_32F row of 128 each). */
#include <libvslam/frontend/PinholeCamera.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/img/CImage.h>
#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>

#include <vector>

namespace vslam
{
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
class CFeatureExtractor
{
   public:
	/** INI section [vslam_features]: SIFT, and the ratio test every
	 * descriptor match of the front-end passes. */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		static constexpr const char* kSection = "vslam_features";

		int sift_features = 600;  //!< strongest features kept per image (0: all)
		double sift_contrast_threshold = 0.03;
		/** Images wider than this are scaled down to it (area averaging)
		 * before SIFT, whose first octave doubles whatever it is given: the
		 * finest features then have the detail of an image this wide, and
		 * SIFT's time falls with the square of the scale (0: every image as
		 * it is). A speed setting for large images: 480 at 640x480 cost no
		 * accuracy in the development homes, but on 1024-pixel photographs
		 * it halved recognition across 45-60 degrees of viewpoint change. */
		int sift_max_cols = 0;
		/** Gaussian blur (std, px) of the image before SIFT: a cheap camera's
		 * pixel noise and JPEG blocks make fine-scale extrema that do not repeat
		 * from one image to the next; a slight blur takes them out (0: none,
		 * the paper's SIFT). */
		double sift_denoise_sigma = 0.7;
		/** Lowe's ratio test between the best and second-best match, for
		 * every matching of these features (creation, candidates,
		 * recognition, heading change). */
		double match_ratio = 0.8;

		void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
		void saveToConfigFile(mrpt::config::CConfigFileBase& target, const std::string& section) const override;
	};

	explicit CFeatureExtractor(const TOptions& options);
	/** Features of `image`; `calibration` undistorts them. */
	ImageFeatures extract(const cv::Mat& image, const CImageCalibration& calibration) const;

   private:
	/** Raw (distorted) pixel positions and descriptors of a grey image. */
	std::vector<cv::Point2f> detect(const cv::Mat& grey, cv::Mat& descriptors) const;

	cv::Ptr<cv::SIFT> m_sift;
	int m_maxCols;
	double m_denoiseSigma;
};
}  // namespace vslam

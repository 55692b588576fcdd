/** Where CFeatureExtractor puts its features: at their true pixel positions,
 * whether SIFT sees the image as it is or scaled down. A feature's position
 * is checked without knowing where SIFT should find it: the image turned
 * by 180 degrees has the same features, each at (W - 1 - x, H - 1 - y), so
 * any constant offset in the reported positions shows as twice itself. */
#include <gtest/gtest.h>
#include <libvslam/config/ConfigError.h>
#include <libvslam/frontend/ImageFeatures.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

using namespace vslam;

namespace
{
cv::Mat texturedImage(int cols, int rows)
{
	cv::RNG rng(11);
	cv::Mat image(rows, cols, CV_8UC1);
	rng.fill(image, cv::RNG::UNIFORM, 0, 255);
	cv::GaussianBlur(image, image, {0, 0}, 1.5);
	cv::normalize(image, image, 0, 255, cv::NORM_MINMAX);
	return image;
}

CImageCalibration calibrationOf(int cols, int rows)
{
	mrpt::img::TCamera camera;
	camera.ncols = cols;
	camera.nrows = rows;
	camera.setIntrinsicParamsFromValues(300, 300, (cols - 1) / 2.0, (rows - 1) / 2.0);
	return CImageCalibration::from(camera, cols, rows, CImageCalibration::TOptions(), "test");
}

struct Offsets
{
	size_t paired = 0;
	double medianX = 0, medianY = 0;
};

/** Median of (x + x') - (W - 1) over features found at the same place in
 * the image and in the image turned by 180 degrees: twice the offset. */
Offsets twiceTheOffset(int cols, int rows, int maxCols)
{
	CFeatureExtractor::TOptions o;
	o.sift_max_cols = maxCols;
	const CFeatureExtractor extractor(o);
	const auto calibration = calibrationOf(cols, rows);
	const cv::Mat image = texturedImage(cols, rows);
	cv::Mat turned;
	cv::flip(image, turned, -1);
	const ImageFeatures a = extractor.extract(image, calibration);
	const ImageFeatures b = extractor.extract(turned, calibration);
	std::vector<double> sumX, sumY;
	for (size_t i = 0; i < a.size(); i++)
	{
		for (size_t j = 0; j < b.size(); j++)
		{
			const double dx = a.pixels[i].x + b.pixels[j].x - (cols - 1);
			const double dy = a.pixels[i].y + b.pixels[j].y - (rows - 1);
			if (std::hypot(dx, dy) > 0.7) continue;
			// The same feature (its descriptor is the mirror image, so only
			// positions compare): the first one this close is taken.
			sumX.push_back(dx);
			sumY.push_back(dy);
			break;
		}
	}
	Offsets out;
	out.paired = sumX.size();
	if (sumX.empty()) return out;
	std::nth_element(sumX.begin(), sumX.begin() + sumX.size() / 2, sumX.end());
	std::nth_element(sumY.begin(), sumY.begin() + sumY.size() / 2, sumY.end());
	out.medianX = sumX[sumX.size() / 2];
	out.medianY = sumY[sumY.size() / 2];
	return out;
}

/** Features of images of each size, detected on the image scaled by
 * `scale` (1: as it is), lie where they are, to 0.025 pixels. */
void expectTruePositions(const std::vector<std::pair<int, int>>& sizes, double scale)
{
	for (const auto& [cols, rows] : sizes)
	{
		const int maxCols = scale < 1 ? static_cast<int>(std::lround(cols * scale)) : 0;
		const Offsets o = twiceTheOffset(cols, rows, maxCols);
		ASSERT_GE(o.paired, 100u) << cols << "x" << rows;
		EXPECT_NEAR(o.medianX, 0, 0.05) << cols << "x" << rows;
		EXPECT_NEAR(o.medianY, 0, 0.05) << cols << "x" << rows;
	}
}
}  // namespace

TEST(CFeatureExtractor, FeaturesAreAtTheirTruePixelPositionsOnTheDoubledImage)
{
	// Without the correction OpenCV's positions are a quarter pixel off:
	// twice the offset is 0.5.
	expectTruePositions({{320, 240}, {321, 241}}, 1);
}

TEST(CFeatureExtractor, FeaturesAreAtTheirTruePixelPositionsOnAScaledDownImage)
{
	expectTruePositions({{640, 480}, {641, 481}}, 0.5);
	expectTruePositions({{640, 480}}, 0.75);
}

TEST(CFeatureExtractor, AnImageScaledDownLosesItsFinestFeatures)
{
	// The doubled full image's octave holds the smallest blobs: on the image
	// halved fewer features pass on a fine texture.
	CFeatureExtractor::TOptions fine, coarse;
	fine.sift_features = coarse.sift_features = 0;
	fine.sift_max_cols = 0;
	coarse.sift_max_cols = 160;
	const cv::Mat image = texturedImage(320, 240);
	const auto full = CFeatureExtractor(fine).extract(image, calibrationOf(320, 240));
	const auto halved = CFeatureExtractor(coarse).extract(image, calibrationOf(320, 240));
	EXPECT_GT(halved.size(), 0u);
	EXPECT_LT(halved.size(), full.size());
	EXPECT_EQ(halved.descriptors.rows, static_cast<int>(halved.size()));
	EXPECT_EQ(halved.descriptors.cols, 128);
}

TEST(CFeatureExtractor, AWidthTooSmallForSiftIsAConfigurationError)
{
	const auto load = [](const std::string& value) {
		mrpt::config::CConfigFileMemory ini("[vslam_features]\nsift_max_cols = " + value + "\n");
		CFeatureExtractor::TOptions o;
		o.loadFromConfigFile(ini, "vslam_features");
		return o.sift_max_cols;
	};
	EXPECT_EQ(load("0"), 0);
	EXPECT_EQ(load("32"), 32);
	EXPECT_THROW(load("31"), ConfigError);
	EXPECT_THROW(load("-1"), ConfigError);
}

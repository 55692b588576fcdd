/** The camera's imaging against its model: auto-exposure settles on
 * mid-grey with its lag and stops at its limits, vignetting darkens the
 * corners by the configured share, noise has the shot + read statistics,
 * a turn blurs over the exposure, a covered lens gives only read noise,
 * and the same seed gives the same frame. */
#include <gtest/gtest.h>
#include <libvslam/sim/CameraImaging.h>

#include <cmath>

using namespace vslam;

namespace
{
cv::Mat grey(int v) { return cv::Mat(120, 160, CV_8UC3, cv::Scalar(v, v, v)); }

double meanEncoded(const cv::Mat& m) { return cv::mean(m)[1] / 255; }

TCameraImagingOptions noiseless()
{
	TCameraImagingOptions o;
	o.full_well = 1e9, o.read_noise = 0, o.white_balance_error = 0, o.vignetting = 0;
	return o;
}

/** Frames of a scene of grey level v at a lighting, one every dt. */
double settle(CameraImaging& cam, int v, double lighting, int frames, double dt = 0.2)
{
	cv::Mat img;
	for (int i = 0; i < frames; i++)
	{
		img = grey(v);
		FrameConditions f;
		f.lighting = lighting, f.dt = dt, f.noiseSeed = static_cast<uint64_t>(i);
		cam.capture(img, f);
	}
	return meanEncoded(img);
}
}  // namespace

TEST(CameraImaging, AutoExposureSettlesOnMidGreyWithinItsLimits)
{
	CameraImaging cam(noiseless(), 250, 1);
	EXPECT_NEAR(settle(cam, 120, 0.2, 40), 0.45, 0.02);  // a darker room: longer exposure, then gain
	EXPECT_GT(cam.exposureTime(), 1.0 / 60);
	EXPECT_NEAR(settle(cam, 120, 3.0, 40), 0.45, 0.02);  // brighter: shorter exposure, no gain
	EXPECT_DOUBLE_EQ(cam.gain(), 1.0);
	// Near darkness is beyond the limits: longest exposure, full gain, dark frames.
	const double dark = settle(cam, 120, 0.003, 60);
	EXPECT_LT(dark, 0.2);
	EXPECT_NEAR(cam.exposureTime(), TCameraImagingOptions().max_exposure_time, 1e-9);
	EXPECT_NEAR(cam.gain(), 8, 1e-9);
}

TEST(CameraImaging, AutoExposureLagsBehindALightingChange)
{
	CameraImaging cam(noiseless(), 250, 1);
	settle(cam, 120, 1.0, 40);
	const double first = settle(cam, 120, 0.25, 1);  // the frame after the lights dim
	EXPECT_LT(first, 0.35);
	const double later = settle(cam, 120, 0.25, 10);  // 2 s later: five time constants
	EXPECT_NEAR(later, 0.45, 0.03);

	TCameraImagingOptions fixed = noiseless();
	fixed.auto_exposure = false;
	CameraImaging manual(fixed, 250, 1);
	EXPECT_NEAR(settle(manual, 120, 0.25, 20), std::pow(0.25, 1 / 2.2) * 120 / 255, 0.01);  // never adapts
}

TEST(CameraImaging, VignettingDarkensTheCornersByItsShare)
{
	TCameraImagingOptions o = noiseless();
	o.auto_exposure = false, o.vignetting = 0.3;
	CameraImaging cam(o, 250, 1);
	cv::Mat img = grey(200);
	cam.capture(img, {});
	const double centre = srgbToLinear(img.at<cv::Vec3b>(60, 80)[1] / 255.0);
	const double corner = srgbToLinear(img.at<cv::Vec3b>(0, 0)[1] / 255.0);
	EXPECT_NEAR(corner / centre, 0.7, 0.02);
}

TEST(CameraImaging, NoiseHasTheShotAndReadStatistics)
{
	TCameraImagingOptions o = noiseless();
	o.auto_exposure = false, o.full_well = 2000, o.read_noise = 5;
	CameraImaging cam(o, 250, 1);
	cv::Mat img = grey(128);
	FrameConditions f;
	f.noiseSeed = 3;
	cam.capture(img, f);
	cv::Mat lin;
	img.convertTo(lin, CV_32F, 1 / 255.0);
	cv::pow(lin, 2.2, lin);
	cv::Scalar mean, stddev;
	cv::meanStdDev(lin.reshape(1), mean, stddev);
	const double s = srgbToLinear(128 / 255.0);
	const double expected = std::sqrt(s / 2000 + std::pow(5.0 / 2000, 2));
	EXPECT_NEAR(mean[0], s, 0.005);
	EXPECT_NEAR(stddev[0], expected, 0.15 * expected);  // quantization adds a little

	cv::Mat again = grey(128);
	CameraImaging twin(o, 250, 1);
	twin.capture(again, f);
	EXPECT_EQ(cv::norm(img, again, cv::NORM_INF), 0);  // same seed, same frame

	cv::Mat covered = grey(128);
	f.blackout = true;
	cam.capture(covered, f);
	EXPECT_LT(meanEncoded(covered), 0.06);  // read noise only
}

TEST(CameraImaging, ATurnBlursOverTheExposure)
{
	TCameraImagingOptions o = noiseless();
	o.auto_exposure = false;
	CameraImaging cam(o, 300, 1);
	cv::Mat img = grey(60);
	img.colRange(80, 160).setTo(cv::Scalar(200, 200, 200));
	FrameConditions f;
	f.turnRate = 2.0;  // rad/s over 1/60 s at fx 300: a 10 px smear
	cam.capture(img, f);
	const auto row = img.row(60);
	int smeared = 0;
	for (int x = 60; x < 100; x++)
	{
		const int v = row.at<cv::Vec3b>(0, x)[1];
		smeared += v > 70 && v < 190;
	}
	EXPECT_GE(smeared, 8);
	EXPECT_LE(smeared, 11);
}

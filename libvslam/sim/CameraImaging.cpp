#include <libvslam/sim/CameraImaging.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace vslam
{
namespace
{
constexpr double kGamma = 2.2;
/** The exposure (s at gain 1) at which the rendered values are what the
 * sensor delivers in normal light. */
constexpr double kReferenceExposure = 1.0 / 60;
/** Auto-exposure aims the mean of the encoded image at mid-grey. */
constexpr double kTargetEncodedMean = 0.45;

cv::Mat linearLut()
{
	cv::Mat lut(1, 256, CV_32F);
	for (int v = 0; v < 256; v++) lut.at<float>(0, v) = static_cast<float>(srgbToLinear(v / 255.0));
	return lut;
}

void blur(cv::Mat& f, double horizontalPx, double verticalPx)
{
	const int h = static_cast<int>(std::round(horizontalPx)), v = static_cast<int>(std::round(verticalPx));
	if (h >= 2) cv::blur(f, f, cv::Size(h, 1), cv::Point(-1, -1), cv::BORDER_REPLICATE);
	if (v >= 2) cv::blur(f, f, cv::Size(1, v), cv::Point(-1, -1), cv::BORDER_REPLICATE);
}
}  // namespace

double srgbToLinear(double encoded) { return std::pow(std::clamp(encoded, 0.0, 1.0), kGamma); }

CameraImaging::CameraImaging(const TCameraImagingOptions& options, double fx, uint64_t seed)
	: m_o(options), m_fx(fx), m_seed(seed), m_exposureProduct(kReferenceExposure)
{
	m_exposure = std::min(kReferenceExposure, m_o.max_exposure_time);
	m_gain = std::clamp(kReferenceExposure / m_exposure, 1.0, m_o.max_gain);
}

void CameraImaging::prepareVignette(const cv::Size& size)
{
	if (m_vignette.size() == size) return;
	// cos^4-like falloff, fitted by a quadratic in the radius that loses
	// `vignetting` of the light at the corners.
	m_vignette.create(size, CV_32FC3);
	const double cx = 0.5 * (size.width - 1), cy = 0.5 * (size.height - 1), r2max = cx * cx + cy * cy;
	for (int y = 0; y < size.height; y++)
		for (int x = 0; x < size.width; x++)
		{
			const double r2 = ((x - cx) * (x - cx) + (y - cy) * (y - cy)) / r2max;
			const float f = static_cast<float>(1 - m_o.vignetting * r2);
			m_vignette.at<cv::Vec3f>(y, x) = cv::Vec3f(f, f, f);
		}
}

void CameraImaging::updateWhiteBalance(int epoch)
{
	if (epoch == m_wbEpoch) return;
	m_wbEpoch = epoch;
	cv::RNG rng(m_seed * 7919 + static_cast<uint64_t>(epoch) + 1);
	// Blue and red drift against green, as an auto white balance misjudges
	// the light's colour.
	const double b = 1 + m_o.white_balance_error * rng.gaussian(1.0), r = 1 + m_o.white_balance_error * rng.gaussian(1.0);
	m_whiteBalance = cv::Scalar(std::max(0.5, b), 1, std::max(0.5, r));
}

void CameraImaging::settleExposure(double measuredMean, double dt)
{
	if (!m_o.auto_exposure) return;
	const double measured = std::max(1e-4, srgbToLinear(measuredMean));
	const double wanted = m_exposureProduct * srgbToLinear(kTargetEncodedMean) / measured;
	const double alpha = 1 - std::exp(-dt / std::max(1e-3, m_o.ae_time_constant));
	const double minExposure = m_o.max_exposure_time / 20;
	m_exposureProduct = std::exp(std::log(m_exposureProduct) + alpha * (std::log(wanted) - std::log(m_exposureProduct)));
	m_exposureProduct = std::clamp(m_exposureProduct, minExposure, m_o.max_exposure_time * m_o.max_gain);
	m_exposure = std::clamp(m_exposureProduct, minExposure, m_o.max_exposure_time);
	m_gain = std::clamp(m_exposureProduct / m_exposure, 1.0, m_o.max_gain);
}

void CameraImaging::capture(cv::Mat& image, const FrameConditions& frame)
{
	static const cv::Mat lut = linearLut();
	prepareVignette(image.size());
	updateWhiteBalance(frame.whiteBalanceEpoch);
	cv::Mat f;
	cv::LUT(image, lut, f);  // linear light, CV_32FC3
	const double light = frame.blackout ? 0.0 : frame.lighting * m_exposure * m_gain / kReferenceExposure;
	f = f.mul(m_vignette, light);
	cv::multiply(f, m_whiteBalance, f);
	blur(f, std::abs(frame.turnRate) * m_exposure * m_fx, frame.bumpBlur);
	// Saturation, then shot noise on the charge collected and read noise,
	// both amplified by the gain.
	cv::min(f, 1.0, f);
	cv::Mat noise(f.size(), f.type());
	cv::RNG(frame.noiseSeed).fill(noise, cv::RNG::NORMAL, 0.0, 1.0);
	const double perElectron = m_gain / m_o.full_well, read = m_o.read_noise * perElectron;
	cv::Mat sigma;
	f.convertTo(sigma, -1, perElectron, read * read);  // every channel (a Mat + double would add to the first only)
	cv::sqrt(sigma, sigma);
	f += noise.mul(sigma);
	cv::max(f, 0.0, f);
	cv::min(f, 1.0, f);
	cv::pow(f, 1 / kGamma, f);
	f.convertTo(image, CV_8U, 255.0);
	const cv::Scalar mean = cv::mean(f);
	settleExposure((mean[0] + mean[1] + mean[2]) / 3, frame.dt);
}
}  // namespace vslam

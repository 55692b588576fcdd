#pragma once
/** \file CameraImaging.h
 * What a cheap robot camera makes of the light a rendered view delivers:
 * auto-exposure that follows the scene's brightness with a lag, within an
 * exposure-time and gain range (a dark room gets long, blurred, noisy
 * frames); lens vignetting; an imperfect white balance that changes with
 * the lighting; motion blur over the exposure from turning and from bumps;
 * photon shot noise and read noise, amplified by the gain; the sRGB gamma
 * and 8-bit quantization. JPEG compression happens when the frame is
 * written (CVisualSimulator). Everything random is drawn from seeds, so a
 * run is repeatable.
 */
#include <opencv2/core.hpp>

#include <cstdint>

namespace vslam
{
struct TCameraImagingOptions
{
	bool auto_exposure = true;
	/** Longest exposure (s); the shortest is a twentieth of it. */
	double max_exposure_time = 0.033;
	double max_gain = 8;  //!< analogue gain limit (1 = none)
	/** How fast the exposure follows a change of brightness (s). */
	double ae_time_constant = 0.4;
	/** Light lost in the image corners relative to the centre (0-1). */
	double vignetting = 0.3;
	/** Standard deviation of the white balance's error per channel. */
	double white_balance_error = 0.04;
	double full_well = 6000;  //!< electrons at saturation at gain 1 (shot noise)
	double read_noise = 4;  //!< electrons (the floor of the noise)
};

/** The state of the camera at one frame and what happens during it. */
struct FrameConditions
{
	double lighting = 1;  //!< scene brightness relative to normal
	double turnRate = 0;  //!< rad/s: horizontal blur over the exposure
	double bumpBlur = 0;  //!< px of vertical blur from a bump during the exposure
	bool blackout = false;  //!< lens covered
	double dt = 0.2;  //!< s since the previous frame (exposure's lag)
	int whiteBalanceEpoch = 0;  //!< a new white balance error after each lighting change
	uint64_t noiseSeed = 0;
};

class CameraImaging
{
   public:
	/** fx: focal length (px) that turns a turn rate into blur; seed: the
	 * run's white balance errors. */
	CameraImaging(const TCameraImagingOptions& options, double fx, uint64_t seed);

	/** The frame this camera delivers for a rendered view (8-bit BGR,
	 * modified in place), and its exposure settles towards the scene. */
	void capture(cv::Mat& image, const FrameConditions& frame);

	double exposureTime() const { return m_exposure; }
	double gain() const { return m_gain; }

   private:
	TCameraImagingOptions m_o;
	double m_fx;
	uint64_t m_seed;
	/** Exposure time x gain (s at gain 1) the controller asks for. */
	double m_exposureProduct;
	double m_exposure, m_gain;
	cv::Mat m_vignette;  //!< per-pixel light falloff, for the last image size
	int m_wbEpoch = -1;
	cv::Scalar m_whiteBalance{1, 1, 1, 0};

	void prepareVignette(const cv::Size& size);
	void updateWhiteBalance(int epoch);
	void settleExposure(double measuredMean, double dt);
};

/** Linear light of an 8-bit sRGB-encoded value (0-1). */
double srgbToLinear(double encoded);
}  // namespace vslam

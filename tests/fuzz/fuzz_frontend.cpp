/** Fuzz target: a camera image with its calibration into the visual
 * front-end. Input: width and height (one byte each, times 4: up to
 * 1020 x 1020), channels (1 or 3), nine doubles (fx fy cx cy k1 k2 p1 p2
 * k3), then pixel bytes (repeated to fill the image). The image goes through
 * the front-end four times along a short odometry path, so features,
 * creation and recognition all run. An std::invalid_argument (unusable
 * calibration) is a clean refusal; a crash, hang, leak or sanitizer report
 * is a finding. */
#include <libvslam/frontend/CVisualFrontEnd.h>

#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	constexpr size_t kHeader = 3 + 9 * sizeof(double);
	if (size < kHeader + 1) return 0;
	const int width = 4 * data[0], height = 4 * data[1];
	const int channels = data[2] % 2 ? 3 : 1;
	if (width == 0 || height == 0) return 0;
	double c[9];
	std::memcpy(c, data + 3, sizeof(c));
	mrpt::obs::CObservationImage obs;
	obs.cameraParams.ncols = width;
	obs.cameraParams.nrows = height;
	obs.cameraParams.setIntrinsicParamsFromValues(c[0], c[1], c[2], c[3]);
	obs.cameraParams.k1(c[4]);
	obs.cameraParams.k2(c[5]);
	obs.cameraParams.p1(c[6]);
	obs.cameraParams.p2(c[7]);
	obs.cameraParams.k3(c[8]);
	obs.cameraPose = mrpt::poses::CPose3D(0, 0, 0.3, -M_PI / 2, 0, -M_PI / 2);
	cv::Mat pixels(height, width, channels == 3 ? CV_8UC3 : CV_8UC1);
	const uint8_t* src = data + kHeader;
	const size_t n = size - kHeader;
	for (size_t i = 0; i < pixels.total() * pixels.elemSize(); i++) pixels.data[i] = src[i % n];
	obs.image = mrpt::img::CImage(pixels, mrpt::img::SHALLOW_COPY);
	vslam::CVisualFrontEnd::TOptions options;
	options.creation.min_points = 6;
	vslam::CVisualFrontEnd frontEnd(options);
	try
	{
		for (int k = 0; k < 4; k++)
		{
			obs.timestamp = mrpt::Clock::fromDouble(1e9 + k);
			frontEnd.process(obs, mrpt::poses::CPose2D(0.2 * k, 0, 0.01 * k), "fuzz image");
		}
	}
	catch (const std::invalid_argument&)
	{
	}
	return 0;
}

#include <libvslam/frontend/InlierSpread.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using vslam::inlierMinorSpread;

namespace
{
const cv::Matx33d kK(500, 0, 320, 0, 500, 240, 0, 0, 1);

/** An nx x ny grid of pixels centred at (cx, cy), `dx` and `dy` apart,
 * turned by `angle` about its centre. */
std::vector<cv::Point2f> grid(int nx, int ny, double dx, double dy, double angle, double cx = 320, double cy = 240)
{
	std::vector<cv::Point2f> px;
	const double c = std::cos(angle), s = std::sin(angle);
	for (int i = 0; i < nx; i++)
		for (int j = 0; j < ny; j++)
		{
			const double x = (i - 0.5 * (nx - 1)) * dx, y = (j - 0.5 * (ny - 1)) * dy;
			px.emplace_back(static_cast<float>(cx + c * x - s * y), static_cast<float>(cy + s * x + c * y));
		}
	return px;
}

/** Population std of n equally spaced values `step` apart. */
double stdOfSpacing(int n, double step) { return step * std::sqrt((n * n - 1) / 12.0); }
}  // namespace

TEST(InlierSpread, IsTheStdAcrossTheNarrowDirectionInRadians)
{
	// 20 x 5 pixels, 10 px apart: across, the std is stdOfSpacing(5, 10) px
	// = 14.14 px, or 0.0283 rad at fx = 500.
	const double expected = stdOfSpacing(5, 10) / 500;
	EXPECT_NEAR(inlierMinorSpread(grid(20, 5, 10, 10, 0), kK), expected, 1e-6);
	EXPECT_NEAR(inlierMinorSpread(grid(5, 20, 10, 10, 0), kK), expected, 1e-6) << "a vertical strip";
	EXPECT_NEAR(inlierMinorSpread(grid(20, 5, 10, 10, 0.7), kK), expected, 1e-5) << "turned";
	EXPECT_NEAR(inlierMinorSpread(grid(20, 5, 10, 10, 0, 100, 400), kK), expected, 1e-6) << "off centre";
}

TEST(InlierSpread, DoesNotDependOnTheResolutionOrTheNumberOfPoints)
{
	const double base = inlierMinorSpread(grid(20, 5, 10, 10, 0.3), kK);
	const cv::Matx33d doubled(1000, 0, 640, 0, 1000, 480, 0, 0, 1);
	EXPECT_NEAR(inlierMinorSpread(grid(20, 5, 20, 20, 0.3, 640, 480), doubled), base, 1e-6);
	// Each point twice: the same distribution, the same spread.
	auto twice = grid(20, 5, 10, 10, 0.3);
	const auto once = twice;
	twice.insert(twice.end(), once.begin(), once.end());
	EXPECT_NEAR(inlierMinorSpread(twice, kK), base, 1e-9);
}

TEST(InlierSpread, ALineHasNoneAndSoHaveFewerThanTwoPoints)
{
	EXPECT_NEAR(inlierMinorSpread(grid(30, 1, 10, 10, 0.4), kK), 0, 1e-5);
	EXPECT_EQ(inlierMinorSpread({}, kK), 0);
	EXPECT_EQ(inlierMinorSpread({cv::Point2f(10, 10)}, kK), 0);
	// Non-square pixels: each axis in its own focal length.
	const cv::Matx33d anisotropic(500, 0, 320, 0, 250, 240, 0, 0, 1);
	EXPECT_NEAR(inlierMinorSpread(grid(5, 20, 10, 10, 0), anisotropic), stdOfSpacing(5, 10) / 500, 1e-6);
	EXPECT_NEAR(inlierMinorSpread(grid(40, 5, 10, 10, 0), anisotropic), stdOfSpacing(5, 10) / 250, 1e-6);
}

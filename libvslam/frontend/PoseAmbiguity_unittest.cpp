#include <gtest/gtest.h>
#include <libvslam/frontend/PoseAmbiguity.h>

#include <opencv2/calib3d.hpp>

#include <random>

using namespace vslam;

namespace
{
constexpr double kDeg = CV_PI / 180;
const cv::Matx33d kK(256, 0, 160, 0, 256, 120, 0, 0, 1);

/** n points on the square of side `size` in the plane z = 0, centred at the
 * origin; with `relief` > 0 spread that far off the plane. */
std::vector<cv::Point3f> squarePoints(int n, double size, double relief, std::mt19937& rng)
{
	std::uniform_real_distribution<double> u(-size / 2, size / 2), r(-relief, relief);
	std::vector<cv::Point3f> p;
	for (int i = 0; i < n; i++)
		p.emplace_back(
			static_cast<float>(u(rng)), static_cast<float>(u(rng)), static_cast<float>(relief > 0 ? r(rng) : 0.0));
	return p;
}

/** A camera `distance` from the origin, looking at it from `angle` off the
 * plane's normal (+z), turned about the plane's y axis. */
CameraPoseFit cameraLookingAtOrigin(double distance, double angle)
{
	const cv::Vec3d C(distance * std::sin(angle), 0, distance * std::cos(angle));
	const cv::Vec3d z = -C / distance, x = cv::normalize(cv::Vec3d(0, 1, 0).cross(z)), y = z.cross(x);
	const cv::Matx33d R(x[0], x[1], x[2], y[0], y[1], y[2], z[0], z[1], z[2]);
	CameraPoseFit p;
	cv::Rodrigues(R, p.rvec);
	p.tvec = -(R * C);
	return p;
}

std::vector<cv::Point2f> noisyPixels(
	const std::vector<cv::Point3f>& object, const CameraPoseFit& p, double sigmaPx, std::mt19937& rng)
{
	std::vector<cv::Point2f> px;
	cv::projectPoints(object, p.rvec, p.tvec, kK, cv::noArray(), px);
	std::normal_distribution<float> noise(0.0f, static_cast<float>(sigmaPx));
	for (auto& q : px) q += cv::Point2f(noise(rng), noise(rng));
	return px;
}

/** The pose refined from `start` on the points, as the recognizer has it. */
CameraPoseFit refined(const std::vector<cv::Point3f>& object, const std::vector<cv::Point2f>& pixels, CameraPoseFit start)
{
	cv::Mat rvec(start.rvec), tvec(start.tvec);
	cv::solvePnPRefineLM(object, pixels, kK, cv::noArray(), rvec, tvec);
	CameraPoseFit p{cv::Vec3d(rvec), cv::Vec3d(tvec), 0};
	std::vector<cv::Point2f> projected;
	cv::projectPoints(object, p.rvec, p.tvec, kK, cv::noArray(), projected);
	double sq = 0;
	for (size_t i = 0; i < object.size(); i++) sq += std::pow(cv::norm(projected[i] - pixels[i]), 2);
	p.rmsPx = std::sqrt(sq / static_cast<double>(object.size()));
	return p;
}

/** The angle of the camera centre from the plane's normal, signed about y. */
double viewingAngle(const CameraPoseFit& p)
{
	cv::Matx33d R;
	cv::Rodrigues(p.rvec, R);
	const cv::Vec3d C = -(R.t() * p.tvec);
	return std::atan2(C[0], C[2]);
}
/** n points on a square of `size` (with `relief`) seen from `distance` at
 * `angle` off its normal with `noisePx` of pixel noise, and the pose
 * refined from the truth, as the recognizer has it. */
struct Sighting
{
	std::vector<cv::Point3f> object;
	std::vector<cv::Point2f> pixels;
	CameraPoseFit pose;
};

Sighting sight(int n, double size, double relief, double distance, double angle, double noisePx, uint32_t seed)
{
	std::mt19937 rng(seed);
	Sighting s;
	s.object = squarePoints(n, size, relief, rng);
	s.pixels = noisyPixels(s.object, cameraLookingAtOrigin(distance, angle), noisePx, rng);
	s.pose = refined(s.object, s.pixels, cameraLookingAtOrigin(distance, angle));
	return s;
}
}  // namespace

TEST(PoseAmbiguity, AFarPlaneHasAMirroredPoseThatReprojectsAsWell)
{
	const auto [object, pixels, pose] = sight(30, 0.5, 0, 6.0, 30 * kDeg, 0.5, 3);
	const auto other = competingPose(object, pixels, kK, pose);
	ASSERT_TRUE(other.has_value());
	// The mirror image of the viewing direction about the line of sight,
	// at about the same distance, and the matches barely prefer the truth.
	EXPECT_NEAR(viewingAngle(*other), -30 * kDeg, 10 * kDeg);
	EXPECT_NEAR(cv::norm(other->tvec), 6.0, 0.3);
	EXPECT_LT(std::abs(reprojectionCostGap(pose, *other, object.size())), 9.0);
}

TEST(PoseAmbiguity, AFarSurfaceWithReliefIsAmbiguousToo)
{
	// Not coplanar, which IPPE alone refuses: 2 cm of relief on 0.5 m.
	const auto [object, pixels, pose] = sight(30, 0.5, 0.02, 6.0, -25 * kDeg, 0.5, 7);
	const auto other = competingPose(object, pixels, kK, pose);
	ASSERT_TRUE(other.has_value());
	EXPECT_NEAR(viewingAngle(*other), 25 * kDeg, 10 * kDeg);
	EXPECT_LT(std::abs(reprojectionCostGap(pose, *other, object.size())), 9.0);
}

TEST(PoseAmbiguity, ANearWidePlaneAndPointsInDepthAreNotAmbiguous)
{
	struct Case
	{
		const char* name;
		double size, relief, distance;
		uint32_t seed;
	};
	for (const Case& c : {Case{"near wide plane", 2.0, 0, 2.0, 4}, Case{"points in depth", 1.0, 0.5, 3.0, 5}})
	{
		const auto [object, pixels, pose] = sight(30, c.size, c.relief, c.distance, 30 * kDeg, 0.5, c.seed);
		const auto other = competingPose(object, pixels, kK, pose);
		// Either every seed converges to the pose, or the other minimum is far worse.
		if (other)
		{
			EXPECT_GT(reprojectionCostGap(pose, *other, object.size()), 100.0) << c.name;
		}
	}
}

TEST(PoseAmbiguity, FromTheWrongBranchTheTruthIsTheCompetitorAndTheGapIsNegative)
{
	const auto [object, pixels, pose] = sight(40, 0.8, 0, 4.0, 40 * kDeg, 0.3, 6);
	const auto wrong = competingPose(object, pixels, kK, pose);
	ASSERT_TRUE(wrong.has_value());
	const auto back = competingPose(object, pixels, kK, *wrong);
	ASSERT_TRUE(back.has_value());
	EXPECT_NEAR(viewingAngle(*back), viewingAngle(pose), 1 * kDeg);
	EXPECT_LE(back->rmsPx, wrong->rmsPx + 1e-6);
	EXPECT_LT(reprojectionCostGap(*wrong, *back, object.size()), 0.0);
}

TEST(PoseAmbiguity, TooFewPointsGiveNoCompetitorAndCollinearOnesDoNotThrow)
{
	const std::vector<cv::Point3f> three{{0, 0, 0}, {0.1f, 0, 0}, {0, 0.1f, 0}};
	const CameraPoseFit pose = cameraLookingAtOrigin(2.0, 0);
	std::vector<cv::Point2f> px;
	cv::projectPoints(three, pose.rvec, pose.tvec, kK, cv::noArray(), px);
	EXPECT_FALSE(competingPose(three, px, kK, pose).has_value());
	std::vector<cv::Point3f> line;
	for (int i = 0; i < 8; i++) line.emplace_back(0.1f * static_cast<float>(i), 0, 0);
	cv::projectPoints(line, pose.rvec, pose.tvec, kK, cv::noArray(), px);
	const auto other = competingPose(line, px, kK, pose);  // must not throw
	if (other)
	{
		EXPECT_TRUE(std::isfinite(other->rmsPx));
	}
}

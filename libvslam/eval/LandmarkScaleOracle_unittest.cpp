#include <gtest/gtest.h>
#include <libvslam/eval/LandmarkScaleOracle.h>

#include <cmath>
#include <random>

using namespace vslam;

namespace
{
const se2::Pose kMount{0.1, 0.02, 0.05};

/** The measurement a landmark k times too large gives of the robot at
 * `robotInLandmark` (true pose in the landmark frame). */
se2::Pose scaledMeasurement(const se2::Pose& robotInLandmark, double k)
{
	const se2::Pose camera = se2::compose(robotInLandmark, kMount);
	const se2::Pose scaledCamera{k * camera.x, k * camera.y, camera.phi};
	return se2::inverse(se2::compose(scaledCamera, se2::inverse(kMount)));
}

void expectNear(const se2::Pose& a, const se2::Pose& b, double tol)
{
	EXPECT_NEAR(a.x, b.x, tol);
	EXPECT_NEAR(a.y, b.y, tol);
	EXPECT_NEAR(se2::wrap(a.phi - b.phi), 0.0, tol);
}
}  // namespace

TEST(LandmarkScaleOracle, ScaleOneChangesNothing)
{
	const se2::Pose z{1.3, -0.4, 0.7};
	expectNear(withoutScale(z, kMount, 1.0), z, 1e-12);
}

TEST(LandmarkScaleOracle, ALandmarkTooLargeIsMeasuredTooFarFromItsOriginAndTakenBack)
{
	const se2::Pose robot{-1.5, 0.6, 0.4};
	const se2::Pose truth = se2::inverse(robot);
	const se2::Pose measured = scaledMeasurement(robot, 1.07);
	// Farther from the origin by the camera's share, the heading the same.
	const se2::Pose cm = cameraInLandmark(measured, kMount), ct = cameraInLandmark(truth, kMount);
	EXPECT_NEAR(std::hypot(cm.x, cm.y), 1.07 * std::hypot(ct.x, ct.y), 1e-12);
	EXPECT_NEAR(se2::wrap(measured.phi - truth.phi), 0.0, 1e-12);
	expectNear(withoutScale(measured, kMount, 1.07), truth, 1e-12);
}

TEST(LandmarkScaleOracle, TheFitFindsTheScaleUnderNoise)
{
	std::mt19937 rng(3);
	std::uniform_real_distribution<double> where(-3, 3), heading(-3, 3);
	std::normal_distribution<double> noise(0, 0.01);
	for (const double k : {0.93, 1.0, 1.04})
	{
		std::vector<std::pair<se2::Pose, se2::Pose>> pairs;
		for (int i = 0; i < 400; i++)
		{
			const se2::Pose robot{where(rng), where(rng), heading(rng)};
			se2::Pose z = scaledMeasurement(robot, k);
			z.x += noise(rng), z.y += noise(rng);
			pairs.emplace_back(z, se2::inverse(robot));
		}
		EXPECT_NEAR(fitLandmarkScale(pairs, kMount), k, 0.002) << k;
	}
	EXPECT_EQ(fitLandmarkScale({}, kMount), 1.0);
}

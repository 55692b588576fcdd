#include <gtest/gtest.h>
#include <libvslam/io/OdometryDelay.h>
#include <libvslam/models/SE2.h>

#include <cmath>
#include <random>

using namespace vslam;

namespace
{
/** A robot that drives and turns in bursts (omega switching between 0 and
 * +-0.8 rad/s every few seconds) among four landmarks, with odometry rows
 * at 50 Hz that lead its motion by `delay`; sightings at 5 Hz of the
 * landmarks within 4 m, with bearing noise `bearingStd` and one sighting in
 * twenty a misdetection anywhere in the field of view. */
struct DelayedRobot
{
	std::vector<std::vector<double>> rows;
	std::vector<BearingSighting> sightings;

	DelayedRobot(double delay, double bearingStd)
	{
		std::mt19937 rng(7);
		std::normal_distribution<double> noise(0, bearingStd);
		std::uniform_real_distribution<double> anywhere(-0.6, 0.6);
		const double landmarks[4][2] = {{3, 1}, {-1, 3}, {-3, -1}, {1, -3}};
		const auto command = [](double t) {
			const double phase = std::fmod(t, 6.0);
			const double omega = phase < 2 ? 0.0 : phase < 4 ? 0.8 : -0.5;
			return std::pair<double, double>{0.2, omega};
		};
		for (int i = 0; i <= 50 * 120; i++)
		{
			const double t = i * 0.02;
			const auto [v, w] = command(t);
			rows.push_back({t, v, w});
		}
		// The true motion: the command `delay` later, integrated finely.
		se2::Pose pose{0, 0, 0};
		const double dt = 0.002;
		for (int i = 0; i * dt <= 120; i++)
		{
			const double t = i * dt;
			const auto [v, w] = t >= delay ? command(t - delay) : std::pair<double, double>{0, 0};
			pose = se2::compose(pose, {v * dt, 0, w * dt});
			if (i % 100 != 0 || t < 1) continue;  // 5 Hz
			for (int l = 0; l < 4; l++)
			{
				const double dx = landmarks[l][0] - pose.x, dy = landmarks[l][1] - pose.y;
				const double bearing = se2::wrap(std::atan2(dy, dx) - pose.phi);
				if (std::hypot(dx, dy) > 4 || std::abs(bearing) > 0.6) continue;
				const bool misdetection = (rng() % 20) == 0;
				sightings.push_back({t, 6 + l, std::hypot(dx, dy), misdetection ? anywhere(rng) : bearing + noise(rng)});
			}
		}
	}
};
}  // namespace

TEST(OdometryDelay, FindsTheDelayFromTheSightingsAlone)
{
	for (const double delay : {0.0, 0.15, 0.4})
	{
		const DelayedRobot robot(delay, 0.009);
		const auto estimate = estimateOdometryDelay(robot.rows, robot.sightings);
		ASSERT_TRUE(estimate.has_value()) << "delay " << delay;
		EXPECT_NEAR(*estimate, delay, 0.03) << "delay " << delay;
	}
}

TEST(OdometryDelay, TooFewSightingsTellNothing)
{
	const DelayedRobot robot(0.15, 0.009);
	std::vector<BearingSighting> few(robot.sightings.begin(), robot.sightings.begin() + 20);
	EXPECT_FALSE(estimateOdometryDelay(robot.rows, few).has_value());
	EXPECT_FALSE(estimateOdometryDelay({{0, 0.1, 0}}, robot.sightings).has_value());
}

#include <gtest/gtest.h>
#include <libvslam/app/KeyframesAlongOdometry.h>

#include <cmath>

using namespace vslam;

namespace
{
/** A robot driving a circle of radius 2 m at 0.2 m/s, one pose per 0.1 s. */
se2::Pose onCircle(double t)
{
	const double a = 0.1 * t;
	return {2 * std::sin(a), 2 - 2 * std::cos(a), a};
}

Trajectory sampled(double t0, double t1, double dt, se2::Pose (*poseAt)(double))
{
	Trajectory out;
	for (int i = 0; t0 + i * dt <= t1 + 1e-9; i++) out.push_back({t0 + i * dt, poseAt(t0 + i * dt)});
	return out;
}

double distance(const se2::Pose& a, const se2::Pose& b) { return std::hypot(a.x - b.x, a.y - b.y); }
}  // namespace

TEST(KeyframesAlongOdometry, ExactOdometryGivesThePathBetweenTheKeyframes)
{
	// Odometry in its own frame (starting 1 m off and turned): only its
	// increments may matter.
	const se2::Pose offset{1, -1, 0.7};
	Trajectory odometry = sampled(0, 20, 0.1, onCircle);
	for (auto& p : odometry) p.pose = se2::compose(offset, p.pose);
	const Trajectory keyframes = sampled(3, 17, 2, onCircle);
	const Trajectory path = keyframesAlongOdometry(keyframes, odometry);
	ASSERT_EQ(path.size(), odometry.size());
	for (const auto& p : path)
	{
		EXPECT_LT(distance(p.pose, onCircle(p.t)), 1e-9) << "t " << p.t;
		EXPECT_NEAR(se2::wrap(p.pose.phi - onCircle(p.t).phi), 0, 1e-9) << "t " << p.t;
	}
}

TEST(KeyframesAlongOdometry, PassesThroughEveryKeyframeAndSpreadsTheMismatchByTime)
{
	// Odometry that stands still; keyframes 1 m apart along x every 10 s.
	Trajectory odometry;
	for (int i = 0; i <= 300; i++) odometry.push_back({0.1 * i, {0, 0, 0}});
	const Trajectory keyframes{{5, {0, 0, 0}}, {15, {1, 0, 0}}, {25, {2, 0, 0.2}}};
	const Trajectory path = keyframesAlongOdometry(keyframes, odometry);
	ASSERT_EQ(path.size(), odometry.size());
	for (const auto& p : path)
	{
		// Before the first keyframe and after the last: carried from it alone.
		const double expectedX = p.t <= 5 ? 0 : p.t >= 25 ? 2 : (p.t - 5) / 10;
		EXPECT_NEAR(p.pose.x, expectedX, 1e-9) << "t " << p.t;
		EXPECT_NEAR(p.pose.y, 0, 1e-9) << "t " << p.t;
		const double expectedPhi = p.t <= 15 ? 0 : p.t >= 25 ? 0.2 : 0.2 * (p.t - 15) / 10;
		EXPECT_NEAR(p.pose.phi, expectedPhi, 1e-9) << "t " << p.t;
	}
}

TEST(KeyframesAlongOdometry, KeyframesWithoutAdvancingTimesAreTheirOwnPath)
{
	const Trajectory keyframes{{7, {0, 0, 0}}, {7, {1, 0, 0}}, {7, {2, 0, 0}}};
	const Trajectory path = keyframesAlongOdometry(keyframes, sampled(0, 10, 0.1, onCircle));
	ASSERT_EQ(path.size(), 3u);
	for (size_t k = 0; k < 3; k++) EXPECT_EQ(path[k].pose.x, keyframes[k].pose.x);
}

TEST(KeyframesAlongOdometry, NoKeyframesNoPath)
{
	EXPECT_TRUE(keyframesAlongOdometry({}, sampled(0, 1, 0.1, onCircle)).empty());
	EXPECT_TRUE(keyframesAlongOdometry(sampled(0, 1, 0.1, onCircle), {}).empty());
}

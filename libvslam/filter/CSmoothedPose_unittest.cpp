/** The smoothed pose follows the odometry, takes a correction in with its
 * time constant and never faster than its speed limit, and jumps at a
 * declared kidnap. */
#include <gtest/gtest.h>
#include <libvslam/filter/CSmoothedPose.h>

#include <cmath>

using namespace vslam;

TEST(CSmoothedPose, FollowsTheOdometryAndSpreadsACorrectionOverTime)
{
	CSmoothedPose::TOptions o;
	o.time_constant = 2, o.max_correction_speed = 1e9;
	CSmoothedPose s(o);
	s.update({0, 0, 0}, 0.2, {0, 0, 0}, false);
	// The filter agrees with the odometry: the smoothed pose is the odometry.
	for (int k = 1; k <= 10; k++) s.update({0.1, 0, 0.01}, 0.2, se2::compose(*s.pose(), {0.1, 0, 0.01}), false);
	const se2::Pose here = *s.pose();
	// A correction of 0.5 m to the side arrives at once in the mean: it is
	// taken in as 1 - exp(-t / 2 s).
	const se2::Pose corrected{here.x, here.y + 0.5, here.phi};
	double t = 0;
	for (int k = 0; k < 10; k++, t += 0.2) s.update({0, 0, 0}, 0.2, corrected, false);
	EXPECT_NEAR(s.pose()->y - here.y, 0.5 * (1 - std::exp(-t / 2)), 1e-9);
	EXPECT_NEAR(s.pose()->x, here.x, 1e-9);
}

TEST(CSmoothedPose, NeverCorrectsFasterThanItsLimitButJumpsAtAKidnap)
{
	CSmoothedPose::TOptions o;
	o.time_constant = 0.1, o.max_correction_speed = 0.05;
	CSmoothedPose s(o);
	s.update({0, 0, 0}, 0.2, {0, 0, 0}, false);
	for (int k = 0; k < 10; k++) s.update({0, 0, 0}, 0.2, {1, 0, 0.5}, false);
	EXPECT_NEAR(s.pose()->x, 0.05 * 2.0, 1e-9);  // 2 s at 5 cm/s
	EXPECT_NEAR(s.pose()->phi, 0.05 * 2.0, 1e-9);
	s.update({0, 0, 0}, 0.2, {4, 3, -1}, true);  // the filter declared a kidnap
	EXPECT_DOUBLE_EQ(s.pose()->x, 4);
	EXPECT_DOUBLE_EQ(s.pose()->phi, -1);
}

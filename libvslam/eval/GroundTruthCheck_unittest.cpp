#include <gtest/gtest.h>
#include <libvslam/eval/GroundTruthCheck.h>

#include <cmath>

using namespace vslam;

namespace
{
/** A robot driving a circle of radius r at 0.3 m/s from time t0, 10 Hz. */
Trajectory circle(double t0, double r, double seconds, double phase = 0)
{
	Trajectory tr;
	for (int i = 0; i <= seconds * 10; i++)
	{
		const double a = phase + 0.3 * (i / 10.0) / r;
		tr.push_back({t0 + i / 10.0, {r * std::sin(a), r - r * std::cos(a), a}, i});
	}
	return tr;
}

/** The same path seen by odometry with a few percent of error. */
Trajectory withOdometryError(Trajectory tr)
{
	for (auto& p : tr) p.pose.x *= 1.03, p.pose.y *= 0.98, p.pose.phi *= 1.02;
	return tr;
}
}  // namespace

TEST(GroundTruthCheck, CoverIsTheShareOfStepsTheTruthSpans)
{
	const Trajectory truth = circle(100, 2, 60);
	EXPECT_DOUBLE_EQ(groundTruthCover(circle(100, 2, 60), truth), 1.0);
	EXPECT_NEAR(groundTruthCover(circle(130, 2, 60), truth), 0.5, 0.01);
	EXPECT_EQ(groundTruthCover(circle(500, 2, 60), truth), 0.0);
}

TEST(GroundTruthCheck, TheRunsOwnTruthAgreesWithItsOdometryAnotherRunsDoesNot)
{
	const Trajectory truth = circle(100, 2, 120);
	EXPECT_LT(odometryDisagreement(withOdometryError(truth), truth), 0.05);
	// Another run on the same clock: another circle, another speed.
	const Trajectory other = circle(100, 0.4, 120, 1.0);
	Trajectory parked = other;
	for (auto& p : parked) p.pose = {1, 1, 0};
	EXPECT_GT(odometryDisagreement(withOdometryError(truth), parked), 0.9);
	Trajectory fast = truth;
	for (auto& p : fast) p.pose = {3 * p.pose.x, 3 * p.pose.y, -p.pose.phi};
	EXPECT_GT(odometryDisagreement(withOdometryError(truth), fast), 0.5);
	Trajectory mirrored = truth;
	for (auto& p : mirrored) p.pose = {p.pose.x, -p.pose.y, -p.pose.phi};
	EXPECT_GT(odometryDisagreement(withOdometryError(truth), mirrored), 0.9);
	// A robot that does not move tells nothing.
	EXPECT_TRUE(std::isnan(odometryDisagreement(parked, parked)));
}

#include <gtest/gtest.h>
#include <libvslam/core/InputError.h>
#include <libvslam/eval/AbsoluteTrajectoryError.h>
#include <libvslam/eval/RelativePoseError.h>
#include <mrpt/random/RandomGenerators.h>

using namespace vslam;

namespace
{
/** Straight along x at `speed` m/s, heading 0, sampled every dt. */
Trajectory straightLine(double dt, int n, double speed = 0.2)
{
	Trajectory tr;
	for (int i = 0; i < n; i++) tr.push_back({i * dt, {speed * i * dt, 0, 0}});
	return tr;
}

/** A lap of a circle of radius 1.5 m in 60 s, every dt, heading along it. */
Trajectory circleLap(double dt)
{
	Trajectory tr;
	for (int k = 0; k * dt <= 60; k++)
	{
		const double t = k * dt, a = 2 * M_PI * t / 60;
		tr.push_back({t, {1.5 * std::cos(a), 1.5 * std::sin(a), se2::wrap(a + M_PI / 2)}});
	}
	return tr;
}

TRpeOptions window(TRpeOptions::Window w, double delta)
{
	TRpeOptions o;
	o.window = w;
	o.delta = delta;
	return o;
}
}  // namespace

TEST(RelativePoseError, IdenticalAndRigidlyMovedEstimatesHaveNone)
{
	const Trajectory truth = circleLap(0.1);
	for (const se2::Pose& T : {se2::Pose{0, 0, 0}, se2::Pose{2.0, -1.0, 0.7}})
	{
		Trajectory moved = truth;
		for (auto& p : moved) p.pose = se2::compose(T, p.pose);
		const RpeStats s = computeRpe(moved, truth);
		EXPECT_EQ(s.translation.count, truth.size() - 10);  // the last second has no pair
		EXPECT_NEAR(s.translation.max, 0, 1e-9);
		EXPECT_NEAR(s.rotation.max, 0, 1e-9);
	}
}

TEST(RelativePoseError, IndependentNoiseOfSigmaGivesTwoSigmaOverAnyWindow)
{
	// The error of the motion i -> j is the difference of two independent
	// 2-D noises: E|e|^2 = 4 sigma^2, whatever the window.
	const Trajectory truth = circleLap(0.01);
	Trajectory noisy = truth;
	mrpt::random::CRandomGenerator rng(11);
	const double sigma = 0.05;
	for (auto& p : noisy)
		p.pose.x += sigma * rng.drawGaussian1D_normalized(), p.pose.y += sigma * rng.drawGaussian1D_normalized();
	for (const auto& o : {window(TRpeOptions::Window::Time, 1.0), window(TRpeOptions::Window::Distance, 2.0)})
		EXPECT_NEAR(computeRpe(noisy, truth, o).translation.rmse, 2 * sigma, 0.03 * 2 * sigma);
}

TEST(RelativePoseError, ScaleDriftShowsAsItsShareOfTheDistanceWindow)
{
	// Odometry that overestimates distance by 3%: over every 1 m travelled
	// the motion is 3 cm too long, while the absolute error grows without
	// bound.
	const Trajectory truth = straightLine(0.05, 2000);
	Trajectory drifting = truth;
	for (auto& p : drifting) p.pose.x *= 1.03;
	const RpeStats s = computeRpe(drifting, truth, window(TRpeOptions::Window::Distance, 1.0));
	EXPECT_NEAR(s.translation.mean, 0.03 * s.meanTravelled, 1e-9);
	EXPECT_NEAR(s.meanTravelled, 1.0, 0.01);  // the first pose a window away
	EXPECT_NEAR(s.rotation.max, 0, 1e-12);
	EXPECT_GT(computeAte(drifting, truth).max, 0.5);
}

TEST(RelativePoseError, HeadingDriftShowsAsRotationErrorPerTimeWindow)
{
	const Trajectory truth = circleLap(0.1);
	Trajectory turning = truth;
	for (auto& p : turning) p.pose.phi = se2::wrap(p.pose.phi + 0.01 * p.t);  // 0.01 rad/s
	const RpeStats s = computeRpe(turning, truth, window(TRpeOptions::Window::Time, 2.0));
	EXPECT_NEAR(s.rotation.mean, 0.02, 1e-9);
	EXPECT_NEAR(s.rotation.max, 0.02, 1e-9);
}

TEST(RelativePoseError, TimeShiftOnAStraightLineLeavesTheMotionRight)
{
	// A constant time offset moves every pose 6 cm along the line (ATE) but
	// not the motion between two of them (RPE).
	const Trajectory truth = straightLine(0.01, 3000);
	Trajectory late = straightLine(0.1, 280);
	for (auto& p : late) p.t += 0.3;
	EXPECT_NEAR(computeAte(late, truth).mean, 0.2 * 0.3, 1e-9);
	EXPECT_NEAR(computeRpe(late, truth).translation.max, 0, 1e-9);
}

TEST(RelativePoseError, DifferentSamplingIsInterpolated)
{
	// The estimate at 7 Hz, the truth at 100 Hz, the same motion.
	const Trajectory truth = circleLap(0.01);
	const Trajectory sparse = circleLap(1.0 / 7);
	const RpeStats s = computeRpe(sparse, truth);
	EXPECT_GT(s.translation.count, 350u);
	EXPECT_LT(s.translation.max, 1e-4);  // linear interpolation of a 1.5 m circle at 100 Hz
	EXPECT_LT(s.rotation.max, 1e-9);
}

TEST(RelativePoseError, WindowsAcrossAGapInTheEstimateAreSkipped)
{
	const Trajectory truth = straightLine(0.1, 600);
	Trajectory withGap;
	for (size_t k = 0; k < truth.size(); k++)
		if (k < 200 || k > 300) withGap.push_back(truth[k]);  // nothing from 20 s to 30 s
	withGap.back().pose.x += 1.0;  // a wrong last pose: only its pairs see it
	const RpeStats s = computeRpe(withGap, truth);
	// Pairs one second apart: 200 poses before the gap less their last
	// second's 10, 299 after it less 10, none spanning the gap: 479, of which
	// one includes the wrong pose.
	EXPECT_EQ(s.translation.count, 479u);
	EXPECT_NEAR(s.translation.max, 1.0, 1e-9);
	EXPECT_NEAR(s.translation.median, 0, 1e-9);
	EXPECT_THROW(computeRpe(truth, truth, window(TRpeOptions::Window::Time, 0)), InputError);
}

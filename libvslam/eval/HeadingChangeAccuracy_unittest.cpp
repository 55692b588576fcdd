#include <gtest/gtest.h>
#include <libvslam/eval/HeadingChangeAccuracy.h>

#include <cmath>
#include <random>

using namespace vslam;

namespace
{
constexpr double kDeg = M_PI / 180;

/** A robot turning at 10 deg/s for 20 s, crossing +-180 deg on the way. */
Trajectory turningTruth()
{
	Trajectory t;
	for (int k = 0; k <= 400; k++)
	{
		const double time = 100 + 0.05 * k;
		t.push_back({time, {0, 0, se2::wrap(170 * kDeg + 10 * kDeg * 0.05 * k)}, k});
	}
	return t;
}
}  // namespace

TEST(HeadingChangeAccuracy, ErrorsNormalizedErrorsAndOdometryBesideThem)
{
	const Trajectory truth = turningTruth();
	std::mt19937 rng(1);
	std::normal_distribution<double> N(0, 1);
	std::vector<HeadingChangeRecord> records;
	const double sigma = 0.05 * kDeg;
	for (int k = 0; k < 2000; k++)
	{
		const double t0 = 100.1 + 0.0095 * k, t1 = t0 + 0.4;
		const double trueDphi = 4 * kDeg;  // 10 deg/s over 0.4 s
		// The prediction says half the actual scatter: normalized RMS 2.
		records.push_back({t0, t1, trueDphi + sigma * N(rng), sigma / 2, trueDphi * 1.02});
	}
	records.push_back({300, 300.4, 0, 1, 0});  // beyond the truth
	const auto a = evaluateHeadingChanges(records, truth);
	EXPECT_EQ(a.count, 2000u);
	EXPECT_EQ(a.withoutTruth, 1u);
	EXPECT_NEAR(a.rmsErrorDeg, 0.05, 0.003);
	EXPECT_NEAR(a.medianAbsErrorDeg, 0.674 * 0.05, 0.004);
	EXPECT_NEAR(a.medianPredictedStdDeg, 0.025, 1e-9);
	EXPECT_NEAR(a.rmsNormalizedError, 2.0, 0.1);
	EXPECT_NEAR(a.medianAbsNormalizedError, 2 * 0.674, 0.1);
	EXPECT_NEAR(static_cast<double>(a.beyond3Sigma) / 2000, 0.1336, 0.02);  // P(|z| > 1.5)
	// The odometry's 2% turn bias: 0.08 deg per interval, every time.
	EXPECT_NEAR(a.odometryRmsErrorDeg, 0.08, 1e-6);
	EXPECT_NEAR(a.odometrySumErrorDeg, 2000 * 0.08, 1e-3);
	EXPECT_NEAR(a.sumErrorDeg, 0, 5 * 0.05 * std::sqrt(2000.0));
}

TEST(HeadingChangeAccuracy, NothingToCompareGivesZeros)
{
	const auto a = evaluateHeadingChanges({}, turningTruth());
	EXPECT_EQ(a.count, 0u);
	EXPECT_EQ(a.rmsErrorDeg, 0);
}

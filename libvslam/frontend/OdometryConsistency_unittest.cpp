#include <libvslam/frontend/OdometryConsistency.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace vslam;
using mrpt::math::TPose2D;
using mrpt::poses::CPose2D;

namespace
{
constexpr double kDeg = M_PI / 180;

/** A landmark 3 m ahead and 1 m left of a robot at (1, 2) facing +y,
 * turned 30 deg against it. */
ReportedRecognition earlierAt(double time)
{
	return {time, TPose2D(1, 2, 90 * kDeg), TPose2D(3, 1, 30 * kDeg)};
}

TOdometryConsistencyOptions fiveSeconds()
{
	TOdometryConsistencyOptions t;
	t.horizon = 5;
	return t;
}
}  // namespace

TEST(OdometryConsistency, PredictsTheLandmarkFromTheEarlierRecognitionAndTheMotionSince)
{
	// The landmark frame is at (0, 5) facing 120 deg in the odometry frame.
	// The robot drove 1 m forward, to (1, 3), and turned left to face -x:
	// (0, 5) is now 1 m ahead and 2 m to the right, turned 120 - 180 = -60 deg.
	const CPose2D predicted = predictFromEarlier(earlierAt(0), CPose2D(1, 3, 180 * kDeg));
	EXPECT_NEAR(predicted.x(), 1, 1e-12);
	EXPECT_NEAR(predicted.y(), -2, 1e-12);
	EXPECT_NEAR(predicted.phi(), -60 * kDeg, 1e-12);
	// Standing still: the earlier measurement itself.
	const CPose2D same = predictFromEarlier(earlierAt(0), CPose2D(1, 2, 90 * kDeg));
	EXPECT_NEAR((same - CPose2D(3, 1, 30 * kDeg)).norm(), 0, 1e-12);
}

TEST(OdometryConsistency, AcceptsWithinThePositionToleranceGrowingWithDistance)
{
	const CPose2D now(1, 3, 180 * kDeg);  // predicted: (1, -2, -60 deg), distance sqrt(5)
	const double reach = 0.3 + 0.1 * std::sqrt(5.0);  // the tolerance at about that distance
	const auto agrees = [&](double dx, double dy, double dphi) {
		return agreesWithOdometry(earlierAt(10), 12, now, CPose2D(1 + dx, -2 + dy, (-60 + dphi) * kDeg), fiveSeconds());
	};
	EXPECT_TRUE(agrees(0, 0, 0));
	EXPECT_TRUE(agrees(0.9 * reach, 0, 0));
	EXPECT_FALSE(agrees(0, 1.1 * reach, 0));
	EXPECT_TRUE(agrees(0, 0, 9.9));
	EXPECT_FALSE(agrees(0, 0, -10.1));
	EXPECT_FALSE(agrees(0, 0, 180));
	// A gross error seen on grass textures: 2.6 m and 72 deg off.
	EXPECT_FALSE(agrees(-1.0, 2.4, 72));
	// The relative share: 0.7 m off fails at 3.8 m (0.68 m allowed) and
	// passes at 7.8 m (1.08 m allowed).
	EXPECT_FALSE(agreesWithOdometry(earlierAt(10), 12, CPose2D(1, 2, 90 * kDeg), CPose2D(3.7, 1, 30 * kDeg), fiveSeconds()));
	const ReportedRecognition far{10, TPose2D(1, 2, 90 * kDeg), TPose2D(7, 1, 30 * kDeg)};
	EXPECT_TRUE(agreesWithOdometry(far, 12, CPose2D(1, 2, 90 * kDeg), CPose2D(7.7, 1, 30 * kDeg), fiveSeconds()));
}

TEST(OdometryConsistency, WithoutARecentEarlierRecognitionEverythingAgrees)
{
	const CPose2D now(1, 3, 180 * kDeg);
	const CPose2D wrong(-3, 4, 100 * kDeg);
	EXPECT_FALSE(agreesWithOdometry(earlierAt(10), 14.9, now, wrong, fiveSeconds()));
	EXPECT_TRUE(agreesWithOdometry(earlierAt(10), 15.1, now, wrong, fiveSeconds()));  // older than the horizon
	EXPECT_TRUE(agreesWithOdometry(earlierAt(10), 9, now, wrong, fiveSeconds()));  // later than this image
	EXPECT_TRUE(agreesWithOdometry(std::nullopt, 12, now, wrong, fiveSeconds()));
	EXPECT_TRUE(agreesWithOdometry(earlierAt(10), 12, now, wrong, TOdometryConsistencyOptions()));  // off
}

#include <gtest/gtest.h>
#include <libvslam/tools/MeasurementAccuracy.h>

#include <cmath>

using namespace vslam;

namespace
{
/** The robot drives at 0.2 m/s along x while turning at 0.1 rad/s, sampled
 * every 0.1 s from 0 to 20 s, with no samples between 12 and 14 s. */
Trajectory drivingAndTurning()
{
	Trajectory truth;
	for (int i = 0; i <= 200; i++)
	{
		const double t = 0.1 * i;
		if (t > 12.05 && t < 13.95) continue;
		truth.push_back({t, {0.2 * t, 0.0, 0.1 * t}, -1});
	}
	return truth;
}

/** Where the landmark frame (fx, 0, 0) is seen from the robot at
 * (rx, 0, rphi), written out instead of through se2::between. */
se2::Pose seenFrom(double rx, double rphi, double fx)
{
	const double c = std::cos(rphi), s = std::sin(rphi);
	return {c * (fx - rx), -s * (fx - rx), -rphi};
}

CMeasurementExtractor::TVisualOptions sigmaVis(double stdXY, double stdPhiDeg, double predictedCovScale = 0)
{
	CMeasurementExtractor::TVisualOptions o;
	o.std_dx = o.std_dy = stdXY;
	o.std_dphi = stdPhiDeg * M_PI / 180;
	o.predicted_cov_scale = predictedCovScale;
	return o;
}

LandmarkMeasurementRecord record(double t, int64_t id, const se2::Pose& z, double projErr = 1.0)
{
	LandmarkMeasurementRecord m;
	m.t = t;
	m.landmarkID = id;
	m.z = z;
	m.ProjErrRMS = projErr;
	m.NPoints = 50;
	return m;
}
}  // namespace

TEST(MeasurementAccuracy, TheTrueMeasurementIsTheCreationPoseSeenFromTheRobotsPoseNow)
{
	const Trajectory truth = drivingAndTurning();
	// The frame is the robot's pose at t = 2 s, (0.4, 0, 0.2); the robot is
	// at (2, 0, 1.0) at t = 10 s.
	const auto z = trueLandmarkMeasurement(truth, 10.0, 2.0);
	ASSERT_TRUE(z);
	EXPECT_NEAR(z->x, std::cos(1.0) * (0.4 - 2.0), 1e-9);
	EXPECT_NEAR(z->y, -std::sin(1.0) * (0.4 - 2.0), 1e-9);
	EXPECT_NEAR(z->phi, 0.2 - 1.0, 1e-9);

	// Between samples the truth is interpolated.
	const auto between = trueLandmarkMeasurement(truth, 5.05, 0.0);
	ASSERT_TRUE(between);
	const se2::Pose atHalf = seenFrom(1.01, 0.505, 0.0);
	EXPECT_NEAR(between->x, atHalf.x, 1e-9);
	EXPECT_NEAR(between->y, atHalf.y, 1e-9);
	EXPECT_NEAR(between->phi, atHalf.phi, 1e-9);
}

TEST(MeasurementAccuracy, NoTrueMeasurementOutsideTheTruthOrAcrossAGap)
{
	const Trajectory truth = drivingAndTurning();
	EXPECT_FALSE(trueLandmarkMeasurement(truth, 21.0, 2.0));  // after its end
	EXPECT_FALSE(trueLandmarkMeasurement(truth, 5.0, -1.0));  // created before its start
	EXPECT_FALSE(trueLandmarkMeasurement(truth, 13.0, 2.0));  // in a 2 s gap
	EXPECT_TRUE(trueLandmarkMeasurement(truth, 14.5, 2.0));
}

TEST(MeasurementAccuracy, BeyondThreeSigmaOfSigmaVisInAnyComponent)
{
	const auto sigma = sigmaVis(0.1, 2.0);
	const se2::Pose truth{1.0, 0.5, 0.3};
	EXPECT_FALSE(beyondThreeSigma({1.29, 0.5, 0.3}, truth, sigma));
	EXPECT_TRUE(beyondThreeSigma({1.31, 0.5, 0.3}, truth, sigma));
	EXPECT_TRUE(beyondThreeSigma({1.0, 0.19, 0.3}, truth, sigma));
	EXPECT_FALSE(beyondThreeSigma({1.0, 0.5, 0.3 + 5.9 * M_PI / 180}, truth, sigma));
	EXPECT_TRUE(beyondThreeSigma({1.0, 0.5, 0.3 - 6.1 * M_PI / 180}, truth, sigma));
	// The heading difference is wrapped: 2 deg across +-180 deg is 2 deg.
	EXPECT_FALSE(beyondThreeSigma({1.0, 0.5, M_PI - 0.0175}, {1.0, 0.5, -M_PI + 0.0175}, sigma));
}

TEST(MeasurementAccuracy, ItsNoiseIsSigmaVisWidenedByTheScaledPredictedCovariance)
{
	auto m = record(0, 1, {1.5, 0.5, 0.3});
	m.predictedStdX = 0.05, m.predictedStdY = 0.01, m.predictedStdPhi = 1.0 * M_PI / 180;
	const se2::Pose truth{1.0, 0.5, 0.3};  // 0.5 m off in x

	// Without weighting its noise is Sigma_vis, whatever it predicts.
	const auto plain = sigmaVis(0.1, 2.0);
	EXPECT_NEAR(measurementStd(m, plain)[0], 0.1, 1e-12);
	EXPECT_TRUE(beyondThreeSigmaOfItsNoise(m, truth, plain));
	EXPECT_EQ(beyondThreeSigmaOfItsNoise(m, truth, plain), beyondThreeSigma(m.z, truth, plain));

	// Weighted with a factor of 4: std x = sqrt(0.1^2 + 16 x 0.05^2) = 0.2236 m,
	// 3 sigma = 0.671 m, so 0.5 m is within and 0.7 m is not.
	const auto weighted = sigmaVis(0.1, 2.0, 4.0);
	const Eigen::Vector3d std = measurementStd(m, weighted);
	EXPECT_NEAR(std[0], std::sqrt(0.05), 1e-12);
	EXPECT_NEAR(std[1], std::sqrt(0.01 + 16 * 0.0001), 1e-12);
	EXPECT_NEAR(std[2], std::sqrt(4.0 + 16 * 1.0) * M_PI / 180, 1e-12);
	EXPECT_TRUE(beyondThreeSigma(m.z, truth, weighted));  // Sigma_vis alone still counts it
	EXPECT_FALSE(beyondThreeSigmaOfItsNoise(m, truth, weighted));
	m.z.x = 1.7;
	EXPECT_TRUE(beyondThreeSigmaOfItsNoise(m, truth, weighted));
}

TEST(MeasurementAccuracy, CountsAllAndAcceptedAndThoseWithoutTruth)
{
	const Trajectory truth = drivingAndTurning();
	const std::map<int64_t, double> created{{1, 2.0}, {2, 4.0}};
	const auto trueZ = [&](double t, int64_t id) { return *trueLandmarkMeasurement(truth, t, created.at(id)); };
	const auto off = [](se2::Pose p, double dx, double dphi) {
		p.x += dx;
		p.phi += dphi;
		return p;
	};

	std::vector<LandmarkMeasurementRecord> ms;
	ms.push_back(record(5.0, 1, off(trueZ(5.0, 1), 0.02, 0.0)));  // good
	ms.push_back(record(6.0, 1, off(trueZ(6.0, 1), -0.04, 0.01)));  // good
	ms.push_back(record(7.0, 2, off(trueZ(7.0, 2), 0.5, 0.0)));  // beyond 3 sigma of Sigma_vis
	ms.back().predictedStdX = 0.2;  // ... but not of its weighted noise
	ms.push_back(record(8.0, 2, off(trueZ(8.0, 2), 0.0, 0.3), 5.0));  // beyond, and rejected by ProjErrRMS
	ms.push_back(record(9.0, 3, {1, 1, 0}));  // a landmark whose creation is unknown
	ms.push_back(record(13.0, 1, {1, 1, 0}));  // in the truth's gap

	CPreFilter::TOptions prefilter;
	prefilter.max_ProjErrRMS = 3.0;
	const auto a = evaluateMeasurements(ms, created, truth, sigmaVis(0.1, 2.0, 4.0), prefilter);

	EXPECT_EQ(a.measurements, 6u);
	EXPECT_EQ(a.withoutTruth, 2u);
	ASSERT_EQ(a.errors.size(), 4u);
	EXPECT_EQ(a.all.count, 4u);
	EXPECT_EQ(a.accepted.count, 3u);
	EXPECT_FALSE(a.errors[3].accepted);
	EXPECT_EQ(a.all.beyond3Sigma, 2u);
	EXPECT_EQ(a.accepted.beyond3Sigma, 1u);
	EXPECT_EQ(a.all.beyond3SigmaOfItsNoise, 1u);  // the 0.3 rad one: its predicted std is 0
	EXPECT_EQ(a.accepted.beyond3SigmaOfItsNoise, 0u);
	EXPECT_TRUE(a.errors[2].beyond3Sigma);
	EXPECT_FALSE(a.errors[2].beyond3SigmaOfItsNoise);
	EXPECT_NEAR(a.errors[1].error[0], -0.04, 1e-9);
	EXPECT_NEAR(a.errors[1].error[2], 0.01, 1e-9);

	// Accepted: position errors 0.02, 0.04, 0.5 m; headings 0, 0.01, 0 rad.
	EXPECT_NEAR(a.accepted.medianPosition, 0.04, 1e-9);
	EXPECT_NEAR(a.accepted.rmsPosition, std::sqrt((0.02 * 0.02 + 0.04 * 0.04 + 0.25) / 3), 1e-9);
	EXPECT_NEAR(a.accepted.medianHeadingDeg, 0.0, 1e-9);
	EXPECT_NEAR(a.accepted.rmsHeadingDeg, std::sqrt(0.0001 / 3) * 180 / M_PI, 1e-9);
	EXPECT_NEAR(a.accepted.shareBeyond3Sigma(), 1.0 / 3, 1e-12);

	// e^T D^-1 e of the four with truth: 0.02 m, (-0.04 m, 0.01 rad), 0.5 m
	// (its own std sqrt(0.01 + 16 x 0.04) m) and 0.3 rad.
	const double sigmaPhi = 2.0 * M_PI / 180;
	const double second = 0.04 * 0.04 / 0.01 + 0.0001 / (sigmaPhi * sigmaPhi);
	const double wideVis = 0.25 / 0.01, wideOwn = 0.25 / 0.65, heading = 0.09 / (sigmaPhi * sigmaPhi);
	// Four values: the upper median (Median.h).
	EXPECT_NEAR(a.all.medianNeesSigmaVis, wideVis, 1e-6);
	EXPECT_NEAR(a.all.medianNeesItsNoise, wideOwn, 1e-6);
	EXPECT_NEAR(a.accepted.medianNeesSigmaVis, second, 1e-6);
	EXPECT_NEAR(normalizedSquaredError(ms[3].z, trueZ(8.0, 2), {0.1, 0.1, sigmaPhi}), heading, 1e-6);
	EXPECT_NEAR(a.accepted.medianNeesItsNoise, second, 1e-6);  // of 0.04, second, wideOwn
}

#include <gtest/gtest.h>
#include <libvslam/models/MeasurementUpdate.h>

#include <Eigen/LU>

using namespace vslam;

TEST(MeasurementUpdate, PoseLandmarkUpdateEqualsInformationFormFusion)
{
	// For pose landmarks h is linear in the landmark given s:
	// z = A (l - [s.xy; s.phi]) with A = blockdiag(R(phi)^T, 1). The Kalman
	// update must equal the exact information-form posterior.
	const auto& model = landmarkModel(LandmarkKind::Pose);
	const se2::Pose s{0.3, -0.2, 0.8};
	LandmarkEstimate l;
	l.kind = LandmarkKind::Pose;
	l.mean << 2.0, 1.0, 0.5;
	l.cov << 0.04, 0.01, 0.002, 0.01, 0.09, -0.003, 0.002, -0.003, 0.01;
	LandmarkMeasurement m;
	m.key = {LandmarkKind::Pose, 1};
	m.z.resize(3);
	m.z << 1.2, 0.1, -0.25;
	m.R = MatN(3, 3);
	m.R.setZero();
	m.R.diagonal() << 0.0081, 0.0081, 0.0019;

	// Exact posterior: measurement of l: y = A^-1 z + s (linear, no wrap
	// issues at these values).
	const Eigen::Matrix3d A = se2::jacBetweenB(s, {0, 0, 0});
	const Eigen::Vector3d y =
		A.inverse() * Eigen::Vector3d(m.z) + Eigen::Vector3d(s.x, s.y, s.phi);
	const Eigen::Matrix3d Ry =
		A.inverse() * Eigen::Matrix3d(m.R) * A.inverse().transpose();
	const Eigen::Matrix3d info = l.cov.inverse() + Ry.inverse();
	const Eigen::Matrix3d Cpost = info.inverse();
	const Eigen::Vector3d mpost =
		Cpost * (l.cov.inverse() * l.mean + Ry.inverse() * y);

	const auto e = evaluateMeasurement(model, s, l, m);
	kalmanUpdate(l, e);
	EXPECT_TRUE(l.mean.isApprox(mpost, 1e-9)) << l.mean.transpose();
	EXPECT_TRUE(l.cov.isApprox(Cpost, 1e-9));
	EXPECT_EQ(l.updates, 1u);
}

TEST(MeasurementUpdate, PointLandmarkUpdateShrinksUncertaintyTowardsTheMeasurement)
{
	const auto& model = landmarkModel(LandmarkKind::Point);
	const se2::Pose s{0, 0, 0};
	LandmarkEstimate l;
	l.kind = LandmarkKind::Point;
	l.mean << 2.0, 0.0, 0.0;
	l.cov.setZero();
	l.cov.topLeftCorner<2, 2>() = Eigen::Matrix2d::Identity() * 0.04;
	LandmarkMeasurement m;
	m.key = {LandmarkKind::Point, 1};
	m.z.resize(2);
	m.z << 2.2, 0.0;
	m.R = MatN(2, 2);
	m.R << 0.04, 0, 0, 0.01;
	const auto e = evaluateMeasurement(model, s, l, m);
	EXPECT_NEAR(e.innovation[0], 0.2, 1e-12);
	EXPECT_NEAR(e.gaussian.mahalanobis2, 0.2 * 0.2 / 0.08, 1e-12);
	kalmanUpdate(l, e);
	EXPECT_NEAR(l.mean[0], 2.1, 1e-12);  // equal variances: halfway
	EXPECT_NEAR(l.cov(0, 0), 0.02, 1e-12);
	EXPECT_EQ(l.cov(2, 2), 0.0);  // the unused block stays untouched
}

TEST(MeasurementUpdate, RobotPoseCovarianceWidensTheInnovation)
{
	const auto& model = landmarkModel(LandmarkKind::Pose);
	LandmarkEstimate l;
	l.kind = LandmarkKind::Pose;
	l.mean << 1, 0, 0;
	LandmarkMeasurement m;
	m.key = {LandmarkKind::Pose, 1};
	m.z = VecN::Zero(3);
	m.z[0] = 1;
	m.R = MatN::Identity(3, 3) * 0.01;
	const Eigen::Matrix3d C = Eigen::Matrix3d::Identity() * 0.05;
	const auto e0 = evaluateMeasurement(model, {0, 0, 0}, l, m);
	const auto e1 = evaluateMeasurement(model, {0, 0, 0}, l, m, &C);
	EXPECT_NEAR(e1.S(0, 0) - e0.S(0, 0), 0.05, 1e-12);
	EXPECT_GT(e1.S(1, 1) - e0.S(1, 1), 0.05);  // heading lever arm
}

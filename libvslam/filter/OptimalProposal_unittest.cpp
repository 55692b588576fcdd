#include <gtest/gtest.h>
#include <libvslam/filter/MotionPrior.h>
#include <libvslam/filter/OptimalProposal.h>
#include <tests/support/Measurements.h>

#include <Eigen/LU>

using namespace vslam;

TEST(OptimalProposal, IsTheKalmanPosteriorOfThePredictedPose)
{
	// A single pose measurement of a perfectly known landmark: the proposal
	// must be the Gaussian fusion of the odometry prior and the pose
	// implied by the measurement (computed here in information form).
	CMotionModel::TOptions o;
	o.sigma_T = 0.3;
	o.sigma_R = 0.3;
	o.sigma_R_per_meter = 0.1;
	const CMotionModel model(o);
	COdometryAccumulator acc;
	acc.add({1, 0, 0}, model.incrementCovariance({1, 0, 0}));
	const MotionPrior mp(acc, model);
	LandmarkBank bank;
	LandmarkEstimate l;
	l.kind = LandmarkKind::Pose;
	l.mean << 3, 0.5, 0.2;
	l.cov = Eigen::Matrix3d::Identity() * 1e-12;
	bank.push_back(l);
	const se2::Pose truth{1.1, -0.05, 0.02};
	const auto m = vslam::testing::poseMeasurement(1, se2::between(truth, {3, 0.5, 0.2}), 0.05, 0.02);
	const auto q = optimalProposal(se2::compose({0, 0, 0}, mp.increment()), mp.globalCov({0, 0, 0}), bank, {KnownMeasurement{&m, 0, 0, 0}}, CRobustLikelihood());
	ASSERT_TRUE(q.valid);
	// The measurement implies s = l (+) z^-1 with covariance J R J^T.
	const se2::Pose zInv = se2::inverse({m.z[0], m.z[1], m.z[2]});
	const se2::Pose implied = se2::compose({3, 0.5, 0.2}, zInv);
	const Eigen::Matrix3d J = se2::jacComposeB({3, 0.5, 0.2}, zInv) *
		se2::jacInverse({m.z[0], m.z[1], m.z[2]});
	const Eigen::Matrix3d Rs = J * Eigen::Matrix3d(m.R) * J.transpose();
	const Eigen::Matrix3d P = mp.globalCov({0, 0, 0});
	const Eigen::Matrix3d C = (P.inverse() + Rs.inverse()).inverse();
	const Eigen::Vector3d mean =
		C * (P.inverse() * Eigen::Vector3d(1, 0, 0) + Rs.inverse() * se2::toVector(implied));
	EXPECT_NEAR(q.mean.x, mean[0], 2e-3);
	EXPECT_NEAR(q.mean.y, mean[1], 2e-3);
	EXPECT_NEAR(q.mean.phi, mean[2], 2e-3);
	EXPECT_TRUE(q.cov.isApprox(C, 0.05)) << q.cov << "\n\n" << C;
}

TEST(OptimalProposal, IgnoresMeasurementsOutsideTheGate)
{
	const CMotionModel model;
	COdometryAccumulator acc;
	acc.add({0.2, 0, 0}, model.incrementCovariance({0.2, 0, 0}));
	const MotionPrior mp(acc, model);
	LandmarkBank bank;
	LandmarkEstimate l;
	l.kind = LandmarkKind::Pose;
	l.mean << 2, 0, 0;
	l.cov = Eigen::Matrix3d::Identity() * 1e-4;
	bank.push_back(l);
	const auto outlier = vslam::testing::poseMeasurement(1, {-3, 4, 1});
	const auto q = optimalProposal(se2::compose({0, 0, 0}, mp.increment()), mp.globalCov({0, 0, 0}), bank, {KnownMeasurement{&outlier, 0, 0, 0}}, CRobustLikelihood());
	EXPECT_NEAR(q.mean.x, 0.2, 1e-12);  // the motion prediction, unchanged
	EXPECT_TRUE(q.cov.isApprox(mp.globalCov({0, 0, 0})));
}

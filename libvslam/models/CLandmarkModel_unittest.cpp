#include <gtest/gtest.h>
#include <libvslam/models/CLandmarkModel.h>
#include <mrpt/random/RandomGenerators.h>
#include <tests/support/NumericalDerivative.h>

using namespace vslam;
using vslam::testing::numericalJacobian;
using vslam::testing::poseVec;
using vslam::testing::vecPose;

namespace
{
LandmarkMeasurement poseMeasurement(const se2::Pose& z)
{
	LandmarkMeasurement m;
	m.key = {LandmarkKind::Pose, 7};
	m.z.resize(3);
	m.z << z.x, z.y, z.phi;
	m.R = MatN(3, 3);
	m.R.setZero();
	m.R.diagonal() << 0.01, 0.02, 0.003;
	return m;
}

LandmarkMeasurement pointMeasurement(double r, double b, const se2::Pose& sensor)
{
	LandmarkMeasurement m;
	m.key = {LandmarkKind::Point, 3};
	m.z.resize(2);
	m.z << r, b;
	m.R = MatN(2, 2);
	m.R << 0.01, 0.0, 0.0, 0.0004;
	m.sensorPose = sensor;
	return m;
}

LandmarkEstimate landmarkAt(LandmarkKind kind, const Eigen::Vector3d& mean)
{
	LandmarkEstimate l;
	l.kind = kind;
	l.mean = mean;
	l.cov = Eigen::Matrix3d::Identity() * 0.01;
	if (kind == LandmarkKind::Point) l.cov(2, 2) = 0;
	return l;
}
}  // namespace

TEST(CPoseLandmarkModel, PredictionJacobiansMatchNumerical)
{
	mrpt::random::CRandomGenerator rng(3);
	const auto& model = landmarkModel(LandmarkKind::Pose);
	const auto m = poseMeasurement({1, 0, 0});
	for (int i = 0; i < 30; i++)
	{
		const se2::Pose s{rng.drawUniform(-3, 3), rng.drawUniform(-3, 3),
						  rng.drawUniform(-3, 3)};
		const auto l = landmarkAt(
			LandmarkKind::Pose,
			{rng.drawUniform(-3, 3), rng.drawUniform(-3, 3),
			 rng.drawUniform(-3, 3)});
		const auto p = model.predict(s, l, m);
		const auto hOfS = [&](const Eigen::VectorXd& x) {
			return Eigen::VectorXd(model.predict(vecPose(x), l, m).zhat);
		};
		const auto hOfL = [&](const Eigen::VectorXd& x) {
			auto l2 = l;
			l2.mean = x;
			return Eigen::VectorXd(model.predict(s, l2, m).zhat);
		};
		EXPECT_TRUE(Eigen::MatrixXd(p.H_robot).isApprox(
			numericalJacobian(hOfS, poseVec(s), {2}), 1e-6));
		EXPECT_TRUE(Eigen::MatrixXd(p.H_landmark).isApprox(
			numericalJacobian(hOfL, l.mean, {2}), 1e-6));
	}
}

TEST(CPoseLandmarkModel, InitializationInvertsPrediction)
{
	const auto& model = landmarkModel(LandmarkKind::Pose);
	const se2::Pose s{1, 2, 0.7};
	const auto m = poseMeasurement({0.5, -0.3, 2.9});
	const LandmarkEstimate l = model.initialize(s, m);
	const auto p = model.predict(s, l, m);
	EXPECT_NEAR(model.innovation(m, p.zhat).norm(), 0, 1e-12);
	// Covariance = J R J^T with J the numerical Jacobian of the inverse model.
	const auto inv = [&](const Eigen::VectorXd& z) {
		return poseVec(se2::compose(s, vecPose(z)));
	};
	const Eigen::MatrixXd J =
		numericalJacobian(inv, Eigen::Vector3d(m.z), {2});
	EXPECT_TRUE(l.cov.isApprox(J * Eigen::MatrixXd(m.R) * J.transpose(), 1e-6));
}

TEST(CPoseLandmarkModel, DualProposalExplainsTheMeasurement)
{
	const auto& model = landmarkModel(LandmarkKind::Pose);
	auto l = landmarkAt(LandmarkKind::Pose, {3, 1, 0.4});
	const auto m = poseMeasurement({1.5, 0.2, -0.3});
	const auto q = model.dualProposal(l, m, HeadingPrior{});
	ASSERT_TRUE(q.valid());
	// Mean: the robot pose from which the landmark is seen exactly at z.
	mrpt::random::CRandomGenerator rng(4);
	Eigen::Vector3d mean = Eigen::Vector3d::Zero();
	const int N = 20000;
	std::vector<se2::Pose> samples;
	for (int i = 0; i < N; i++) samples.push_back(q.sample(rng));
	for (const auto& s : samples) mean += poseVec(s);
	mean /= N;
	const auto p = model.predict(vecPose(mean), l, m);
	EXPECT_LT(model.innovation(m, p.zhat).norm(), 0.01);
	// Covariance: numerically propagate (l, z) -> s = l (+) z^-1.
	const auto dual = [&](const Eigen::VectorXd& lz) {
		return poseVec(se2::compose(
			vecPose(lz.head(3)), se2::inverse(vecPose(lz.tail(3)))));
	};
	Eigen::VectorXd lz(6);
	lz << l.mean, Eigen::Vector3d(m.z);
	const Eigen::MatrixXd J = numericalJacobian(dual, lz, {2});
	Eigen::MatrixXd Cin = Eigen::MatrixXd::Zero(6, 6);
	Cin.topLeftCorner(3, 3) = l.cov;
	Cin.bottomRightCorner(3, 3) = Eigen::MatrixXd(m.R);
	const Eigen::MatrixXd C = J * Cin * J.transpose();
	Eigen::Matrix3d sampleCov = Eigen::Matrix3d::Zero();
	for (const auto& s : samples)
	{
		const Eigen::Vector3d d = se2::difference(s, vecPose(mean));
		sampleCov += d * d.transpose();
	}
	sampleCov /= N - 1;
	EXPECT_TRUE(sampleCov.isApprox(C, 0.05)) << sampleCov << "\n\n" << C;
}

TEST(CPointLandmarkModel, PredictionJacobiansMatchNumerical)
{
	mrpt::random::CRandomGenerator rng(5);
	const auto& model = landmarkModel(LandmarkKind::Point);
	const auto m = pointMeasurement(1, 0, {0.2, -0.1, 0.3});
	for (int i = 0; i < 30; i++)
	{
		const se2::Pose s{rng.drawUniform(-3, 3), rng.drawUniform(-3, 3),
						  rng.drawUniform(-3, 3)};
		const auto l = landmarkAt(
			LandmarkKind::Point,
			{rng.drawUniform(-3, 3) + 7, rng.drawUniform(-3, 3), 0});
		const auto p = model.predict(s, l, m);
		const auto hOfS = [&](const Eigen::VectorXd& x) {
			return Eigen::VectorXd(model.predict(vecPose(x), l, m).zhat);
		};
		const auto hOfL = [&](const Eigen::VectorXd& x) {
			auto l2 = l;
			l2.mean.head<2>() = x;
			return Eigen::VectorXd(model.predict(s, l2, m).zhat);
		};
		EXPECT_TRUE(Eigen::MatrixXd(p.H_robot).isApprox(
			numericalJacobian(hOfS, poseVec(s), {1}), 1e-6));
		EXPECT_TRUE(Eigen::MatrixXd(p.H_landmark).isApprox(
			numericalJacobian(hOfL, l.mean.head<2>(), {1}), 1e-6));
	}
}

TEST(CPointLandmarkModel, InitializationInvertsPrediction)
{
	const auto& model = landmarkModel(LandmarkKind::Point);
	const se2::Pose s{1, 2, 0.7};
	const se2::Pose sensor{0.1, 0.05, -0.2};
	const auto m = pointMeasurement(2.5, 0.4, sensor);
	const LandmarkEstimate l = model.initialize(s, m);
	const auto p = model.predict(s, l, m);
	EXPECT_NEAR(model.innovation(m, p.zhat).norm(), 0, 1e-12);
	const auto inv = [&](const Eigen::VectorXd& z) {
		auto m2 = m;
		m2.z = z;
		return Eigen::VectorXd(model.initialize(s, m2).mean.head<2>());
	};
	const Eigen::MatrixXd J = numericalJacobian(inv, Eigen::VectorXd(m.z));
	EXPECT_TRUE(Eigen::MatrixXd(l.covN()).isApprox(
		J * Eigen::MatrixXd(m.R) * J.transpose(), 1e-6));
}

TEST(CPointLandmarkModel, DualProposalMeanExplainsTheMeasurement)
{
	const auto& model = landmarkModel(LandmarkKind::Point);
	auto l = landmarkAt(LandmarkKind::Point, {4, 2, 0});
	const se2::Pose sensor{0.1, 0.05, -0.2};
	const auto m = pointMeasurement(2.0, 0.3, sensor);
	const auto q = model.dualProposal(l, m, HeadingPrior::Gaussian(0.5, 0.1));
	ASSERT_TRUE(q.valid());
	// For any heading, the conditional mean position reproduces z exactly.
	for (double phi : {-2.0, 0.0, 0.5, 3.0})
	{
		mrpt::random::CRandomGenerator rng(1);
		// Zero noise: a landmark and measurement without uncertainty.
		auto lExact = l;
		lExact.cov.setZero();
		auto mExact = m;
		mExact.R = MatN::Identity(2, 2) * 1e-16;
		const auto qe =
			model.dualProposal(lExact, mExact, HeadingPrior::Gaussian(phi, 1e-9));
		const se2::Pose s = qe.sample(rng);
		EXPECT_NEAR(s.phi, phi, 1e-6);
		const auto p = model.predict(s, lExact, mExact);
		EXPECT_LT(model.innovation(mExact, p.zhat).norm(), 1e-6);
	}
}

TEST(CLandmarkModel, InverseModelJacobiansMatchNumerical)
{
	const se2::Pose s{1, -2, 0.9};
	for (LandmarkKind kind : {LandmarkKind::Pose, LandmarkKind::Point})
	{
		const auto& model = landmarkModel(kind);
		const auto m = kind == LandmarkKind::Pose ? poseMeasurement({1.2, 0.4, -0.7})
												  : pointMeasurement(2.5, 0.4, {0.1, 0.05, -0.2});
		const auto inv = [&](const Eigen::VectorXd& x) {
			return Eigen::VectorXd(model.initialize(vecPose(x), m).meanN());
		};
		const Eigen::MatrixXd Jn = numericalJacobian(
			inv, poseVec(s), kind == LandmarkKind::Pose ? std::set<int>{2} : std::set<int>{});
		EXPECT_TRUE(Eigen::MatrixXd(model.inverseJacobianRobot(s, m)).isApprox(Jn, 1e-6))
			<< toString(kind);
		// With the robot pose uncertainty, the covariance grows by J C J^T.
		const Eigen::Matrix3d C = Eigen::Vector3d(0.01, 0.02, 0.003).asDiagonal();
		const auto a = model.initialize(s, m), b = model.initialize(s, m, &C);
		EXPECT_TRUE(Eigen::MatrixXd(b.covN() - a.covN()).isApprox(Jn * C * Jn.transpose(), 1e-6));
	}
}


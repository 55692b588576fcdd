#include <gtest/gtest.h>
#include <libvslam/models/CMotionModel.h>
#include <libvslam/models/COdometryAccumulator.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>

using namespace vslam;

namespace
{
/** Odometry noisy enough for a Monte-Carlo check to see its covariance. */
CMotionModel noisyOdometry()
{
	CMotionModel::TOptions o;
	o.sigma_T = 0.05;
	o.sigma_R = 0.05;
	o.sigma_R_per_meter = 0.02;
	return CMotionModel(o);
}
}  // namespace

TEST(COdometryAccumulator, ComposesMeans)
{
	COdometryAccumulator acc;
	EXPECT_TRUE(acc.empty());
	mrpt::poses::CPose2D ref;
	for (int i = 0; i < 20; i++)
	{
		const se2::Pose u{0.1, 0.01 * i, 0.05 * (i % 3 - 1)};
		acc.add(u, Eigen::Matrix3d::Zero());
		ref = ref + mrpt::poses::CPose2D(u);
	}
	EXPECT_FALSE(acc.empty());
	EXPECT_NEAR(acc.mean().x, ref.x(), 1e-12);
	EXPECT_NEAR(acc.mean().y, ref.y(), 1e-12);
	EXPECT_NEAR(acc.mean().phi, ref.phi(), 1e-12);
	acc.reset();
	EXPECT_TRUE(acc.empty());
	EXPECT_EQ(acc.mean().x, 0.0);
}

TEST(COdometryAccumulator, CovarianceMatchesMonteCarlo)
{
	// An out-and-back path: the accumulated covariance must keep the noise
	// of the whole trip although the net displacement is small.
	const CMotionModel model = noisyOdometry();
	std::vector<se2::Pose> incs;
	for (int i = 0; i < 10; i++) incs.push_back({0.1, 0, 0});
	for (int i = 0; i < 10; i++) incs.push_back({0, 0, M_PI / 10});
	for (int i = 0; i < 10; i++) incs.push_back({0.1, 0, 0});

	COdometryAccumulator acc;
	for (const auto& u : incs) acc.add(u, model.incrementCovariance(u));

	mrpt::random::CRandomGenerator rng(7);
	const int N = 20000;
	std::vector<Eigen::Vector3d> samples;
	Eigen::Vector3d mean = Eigen::Vector3d::Zero();
	for (int k = 0; k < N; k++)
	{
		se2::Pose p{0, 0, 0};
		for (const auto& u : incs)
		{
			const Eigen::Matrix3d C = model.incrementCovariance(u);
			const se2::Pose noisy{
				u.x + std::sqrt(C(0, 0)) * rng.drawGaussian1D_normalized(),
				u.y + std::sqrt(C(1, 1)) * rng.drawGaussian1D_normalized(),
				u.phi + std::sqrt(C(2, 2)) * rng.drawGaussian1D_normalized()};
			p = se2::compose(p, noisy);
		}
		// Deviation in the frame where the increment starts (= origin).
		samples.push_back(se2::difference(p, acc.mean()));
		mean += samples.back();
	}
	mean /= N;
	Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
	for (const auto& s : samples) cov += (s - mean) * (s - mean).transpose();
	cov /= N - 1;
	// The whole trip's noise is kept (2 m travelled), not the net motion's.
	EXPECT_GT(acc.cov()(0, 0), 0.9 * model.options.sigma_T * model.options.sigma_T * 2.0);
	for (int r = 0; r < 3; r++)
		for (int c = 0; c < 3; c++)
			EXPECT_NEAR(cov(r, c), acc.cov()(r, c), 0.06 * acc.cov().norm())
				<< r << "," << c;
}

namespace
{
const auto kT0 = mrpt::Clock::fromDouble(100.0), kT1 = mrpt::Clock::fromDouble(100.4),
		   kT2 = mrpt::Clock::fromDouble(100.8);
constexpr double kGate = 10.83;  // chi2(1) at 0.999
}  // namespace

TEST(COdometryAccumulator, AHeadingChangeFromTheStartIsAKalmanUpdateOfTheIncrement)
{
	COdometryAccumulator acc;
	acc.setHeadingReference(kT0);
	const Eigen::Matrix3d C = Eigen::Vector3d(1e-4, 4e-4, 3e-3).asDiagonal();
	acc.add({0.3, 0.0, 0.2}, C);
	acc.add({0.2, 0.0, -0.1}, C);
	const se2::Pose before = acc.mean();
	const Eigen::Matrix3d P = acc.cov();
	const double z = before.phi + 0.04, R = 1e-4;
	ASSERT_EQ(acc.fuseHeadingChange(kT0, kT1, z, R, kGate), COdometryAccumulator::HeadingFusion::Fused);
	// The reference is the start: h = phi of the increment, H = [0 0 1].
	const Eigen::Vector3d K = P.col(2) / (P(2, 2) + R);
	EXPECT_NEAR(acc.mean().x, before.x + K[0] * 0.04, 1e-12);
	EXPECT_NEAR(acc.mean().y, before.y + K[1] * 0.04, 1e-12);
	EXPECT_NEAR(acc.mean().phi, before.phi + K[2] * 0.04, 1e-12);
	const Eigen::Matrix3d expected = P - K * (P(2, 2) + R) * K.transpose();
	EXPECT_LT((acc.cov() - expected).norm(), 1e-15);
	EXPECT_LT(acc.cov()(2, 2), R);  // at least as sure as the measurement
	// The lateral position moves with the heading: it came from the heading.
	EXPECT_NE(K[1], 0.0);
}

TEST(COdometryAccumulator, AReferenceMidwayUsesTheCrossCovarianceOfTheTwoPoses)
{
	// A winding first leg (much heading uncertainty at the reference), then
	// a turn and a straight: the gain of the joint update must equal
	// Cov(s, h) / (Var(h) + R) of sampled paths, h the heading change since
	// the reference.
	const CMotionModel model = noisyOdometry();
	std::vector<se2::Pose> first, second;
	for (int i = 0; i < 8; i++) first.push_back({0.1, 0, i % 2 ? 0.3 : -0.3});
	for (int i = 0; i < 6; i++) second.push_back({0.05, 0, M_PI / 8});
	for (int i = 0; i < 6; i++) second.push_back({0.1, 0, -0.02});
	COdometryAccumulator acc;
	for (const auto& u : first) acc.add(u, model.incrementCovariance(u));
	acc.setHeadingReference(kT0);
	for (const auto& u : second) acc.add(u, model.incrementCovariance(u));
	const se2::Pose before = acc.mean();
	const Eigen::Matrix3d P = acc.cov();
	const double R = 5e-3, nu = 1e-3;
	ASSERT_EQ(acc.fuseHeadingChange(kT0, kT1, before.phi + nu, R, kGate),
		COdometryAccumulator::HeadingFusion::Fused);
	const Eigen::Vector3d gain = se2::difference(acc.mean(), before) / nu;

	mrpt::random::CRandomGenerator rng(3);
	const int N = 40000;
	std::vector<Eigen::Vector4d> samples;  // x, y, phi, h
	Eigen::Vector4d mean = Eigen::Vector4d::Zero();
	for (int k = 0; k < N; k++)
	{
		se2::Pose p{0, 0, 0};
		auto step = [&](const se2::Pose& u) {
			const Eigen::Matrix3d C = model.incrementCovariance(u);
			p = se2::compose(p, {u.x + std::sqrt(C(0, 0)) * rng.drawGaussian1D_normalized(),
									u.y + std::sqrt(C(1, 1)) * rng.drawGaussian1D_normalized(),
									u.phi + std::sqrt(C(2, 2)) * rng.drawGaussian1D_normalized()});
		};
		for (const auto& u : first) step(u);
		const double phiRef = p.phi;
		for (const auto& u : second) step(u);
		samples.emplace_back(p.x, p.y, p.phi, se2::wrap(p.phi - phiRef));
		mean += samples.back();
	}
	mean /= N;
	Eigen::Vector3d covSh = Eigen::Vector3d::Zero();
	double varH = 0;
	for (const auto& s : samples)
	{
		covSh += (s.head<3>() - mean.head<3>()) * (s[3] - mean[3]);
		varH += (s[3] - mean[3]) * (s[3] - mean[3]);
	}
	covSh /= N - 1;
	varH /= N - 1;
	const Eigen::Vector3d expected = covSh / (varH + R);
	for (int i = 0; i < 3; i++) EXPECT_NEAR(gain[i], expected[i], 0.05 * expected.norm()) << i;
	// Without the reference's cross-covariance the gain would be that of
	// the whole increment's heading, P(:, 2) / (P22 + R): beyond four times
	// the tolerance above (here 30% off).
	const Eigen::Vector3d whole = P.col(2) / (P(2, 2) + R);
	EXPECT_GT((whole - expected).norm(), 0.2 * expected.norm());
}

TEST(COdometryAccumulator, AHeadingChangeNeedsItsReference)
{
	using F = COdometryAccumulator::HeadingFusion;
	const Eigen::Matrix3d C = Eigen::Matrix3d::Identity() * 1e-3;
	COdometryAccumulator acc;
	acc.add({0.1, 0, 0.1}, C);
	EXPECT_EQ(acc.fuseHeadingChange(kT0, kT1, 0.1, 1e-4, kGate), F::NoReference);  // the first image
	// ... which made the reference at kT1: the next one fuses.
	acc.add({0.1, 0, 0.1}, C);
	EXPECT_EQ(acc.fuseHeadingChange(kT1, kT2, 0.1, 1e-4, kGate), F::Fused);
	// An update right after the reference keeps it (at the new start) ...
	acc.reset();
	acc.add({0.1, 0, 0.05}, C);
	EXPECT_EQ(acc.fuseHeadingChange(kT2, kT0, 0.05, 1e-4, kGate), F::Fused);
	// ... one after more odometry does not: part of the interval is gone.
	acc.add({0.1, 0, 0.05}, C);
	acc.reset();
	acc.add({0.1, 0, 0.05}, C);
	EXPECT_EQ(acc.fuseHeadingChange(kT0, kT1, 0.1, 1e-4, kGate), F::NoReference);
	// A reference at another time than the measurement's start is no use.
	acc.add({0.1, 0, 0.05}, C);
	EXPECT_EQ(acc.fuseHeadingChange(kT0, kT2, 0.05, 1e-4, kGate), F::NoReference);
}

TEST(COdometryAccumulator, AHeadingChangeMayStartAtAnyReferenceSinceTheLastUpdate)
{
	// References at every odometry reading: a heading change from an older
	// one is the same Kalman update as with that reference alone.
	using F = COdometryAccumulator::HeadingFusion;
	const CMotionModel model = noisyOdometry();
	const std::vector<se2::Pose> path{{0.1, 0, 0.3}, {0.1, 0, -0.2}, {0.05, 0, 0.4}, {0.1, 0, 0.1}};
	const auto time = [](size_t k) { return mrpt::Clock::fromDouble(200.0 + k); };
	COdometryAccumulator alone, every;
	for (size_t k = 0; k < path.size(); k++)
	{
		alone.add(path[k], model.incrementCovariance(path[k]));
		every.add(path[k], model.incrementCovariance(path[k]));
		if (k == 0) alone.setHeadingReference(time(k));
		every.setHeadingReference(time(k));
	}
	const double dphi = 0.3 + 0.01, R = 1e-4;
	ASSERT_EQ(alone.fuseHeadingChange(time(0), time(9), dphi, R, kGate), F::Fused);
	ASSERT_EQ(every.fuseHeadingChange(time(0), time(9), dphi, R, kGate), F::Fused);
	EXPECT_NEAR(every.mean().x, alone.mean().x, 1e-15);
	EXPECT_NEAR(every.mean().y, alone.mean().y, 1e-15);
	EXPECT_NEAR(every.mean().phi, alone.mean().phi, 1e-15);
	EXPECT_LT((every.cov() - alone.cov()).norm(), 1e-15);
	// The fusion leaves one reference, at its end: the older ones are gone.
	every.add(path[0], model.incrementCovariance(path[0]));
	EXPECT_EQ(every.fuseHeadingChange(time(1), time(10), 0.3, R, kGate), F::NoReference);

	// A window of references: the oldest of more than it holds is dropped.
	COdometryAccumulator many;
	for (size_t k = 0; k < 17; k++)
	{
		many.add(path[k % path.size()], model.incrementCovariance(path[k % path.size()]));
		many.setHeadingReference(time(k));
	}
	EXPECT_EQ(many.fuseHeadingChange(time(0), time(20), 0.3, R, kGate), F::NoReference);
	many.add(path[0], model.incrementCovariance(path[0]));
	EXPECT_NE(many.fuseHeadingChange(time(20), time(21), path[0].phi, R, kGate), F::NoReference);
}

TEST(COdometryAccumulator, AHeadingChangeTheOdometryCannotExplainIsGated)
{
	COdometryAccumulator acc;
	acc.setHeadingReference(kT0);
	acc.add({0.1, 0, 0.2}, Eigen::Vector3d(1e-4, 1e-4, 1e-4).asDiagonal());  // heading std 0.57 deg
	const se2::Pose before = acc.mean();
	EXPECT_EQ(acc.fuseHeadingChange(kT0, kT1, 0.2 + 0.1, 1e-6, kGate), COdometryAccumulator::HeadingFusion::Gated);
	EXPECT_EQ(acc.mean().phi, before.phi);
	EXPECT_EQ(acc.cov()(2, 2), 1e-4);
}

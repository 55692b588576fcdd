#include <gtest/gtest.h>
#include <libvslam/core/InputError.h>
#include <libvslam/filter/CVSlamParticleFilter.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/random/RandomGenerators.h>
#include <tests/support/Measurements.h>

#include <Eigen/LU>
#include <cmath>
#include <memory>
#include <string>

using namespace vslam;
using namespace vslam::testing;

namespace
{
/** Weighted mean and covariance of the particle poses. */
void weightedMoments(const CVSlamParticleFilter& f, Eigen::Vector3d& mean, Eigen::Matrix3d& cov)
{
	std::vector<double> w;
	double sum = 0;
	for (size_t i = 0; i < f.particlesCount(); i++) sum += w.emplace_back(std::exp(f.getW(i)));
	mean.setZero();
	for (size_t i = 0; i < w.size(); i++) mean += w[i] / sum * se2::toVector(f.particle(i).pose);
	cov.setZero();
	for (size_t i = 0; i < w.size(); i++)
	{
		const Eigen::Vector3d d = se2::toVector(f.particle(i).pose) - mean;
		cov += w[i] / sum * d * d.transpose();
	}
}

CVSlamParticleFilter::TOptions manyParticles(size_t n)
{
	CVSlamParticleFilter::TOptions o;
	o.pf.sampleSize = static_cast<uint32_t>(n);
	o.kidnap.enabled = false;
	return o;
}

/** n particles drawn around the origin with the given spread; the first
 * landmark anchored at the cloud's mean or not. */
CVSlamParticleFilter::TOptions spreadCloud(size_t n, double stdXY, double stdPhi, bool anchorFirstLandmark)
{
	CVSlamParticleFilter::TOptions o = manyParticles(n);
	o.pf.initial_std_xy = stdXY;
	o.pf.initial_std_phi = stdPhi;
	o.landmarks.anchor_first_landmark = anchorFirstLandmark;
	return o;
}
}  // namespace

TEST(CVSlamParticleFilter, ResamplingResetsTheWeights)
{
	// MRPT 2.5.8 keeps old weights after resampling (pitfall 1).
	mrpt::random::getRandomGenerator().randomize(1);
	CVSlamParticleFilter f(manyParticles(50));
	for (size_t i = 0; i < 50; i++) f.setW(i, -0.1 * i);
	EXPECT_LT(f.ESS(), 0.5);
	f.performResampling(f.options().pf.toMrpt());
	EXPECT_DOUBLE_EQ(f.ESS(), 1.0);
	for (size_t i = 0; i < 50; i++) EXPECT_EQ(f.getW(i), 0.0);
	EXPECT_EQ(f.stats().resamplings, 1u);
}

/** (nominal proposal, dual share) */
class MixturePosterior
	: public ::testing::TestWithParam<std::tuple<CMixtureProposal::Nominal, double>>
{
};

TEST_P(MixturePosterior, MatchesTheAnalyticPosteriorForAnyDualRatio)
{
	// One update with a known landmark: the weighted particles must match
	// the Gaussian posterior whatever share of them is dual. This is the
	// test that nominal and dual importance factors are consistent.
	const auto [nominal, phi] = GetParam();
	auto o = manyParticles(20000);
	o.mixture.nominal_proposal = nominal;
	o.motion.sigma_T = 0.3;
	o.motion.sigma_R = 0.3;
	o.motion.sigma_R_per_meter = 0.1;
	o.mixture.dual_ratio = o.mixture.dual_ratio_max = phi;
	o.mixture.dual_only_if_sharper = false;
	o.likelihood.outlier_probability = 1e-9;
	mrpt::random::getRandomGenerator().randomize(3);
	CVSlamParticleFilter f(o);
	const se2::Pose landmark{2, 0.5, 0.3};
	LandmarkEstimate l = poseLandmark(landmark);
	l.cov.diagonal() << 0.01, 0.01, 0.001;
	f.setPriorMap({{{LandmarkKind::Pose, 1}, l}});
	f.addOdometryIncrement({1, 0, 0});
	const Eigen::Matrix3d P0 =
		MotionPrior(f.pendingOdometry(), CMotionModel(o.motion)).globalCov({0, 0, 0});
	const se2::Pose truth{1.2, -0.1, 0.05};
	const auto m = poseMeasurement(1, se2::between(truth, landmark), 0.06, 0.035);
	f.processFrame(frame(1, {m}));
	EXPECT_EQ(f.lastFrame().dualParticles, static_cast<size_t>(phi * 20000));

	// Gauss-Newton on the linearized problem.
	Eigen::Vector3d x(1, 0, 0), prior(1, 0, 0);
	Eigen::Matrix3d C;
	for (int it = 0; it < 10; it++)
	{
		const se2::Pose s = se2::fromVector(x);
		const Eigen::Matrix3d Hs = se2::jacBetweenA(s, landmark);
		const Eigen::Matrix3d Hl = se2::jacBetweenB(s, landmark);
		const Eigen::Matrix3d R = Eigen::Matrix3d(m.R) + Hl * l.cov * Hl.transpose();
		const Eigen::Vector3d nu = se2::difference(
			{m.z[0], m.z[1], m.z[2]}, se2::between(s, landmark));
		const Eigen::Matrix3d info = P0.inverse() + Hs.transpose() * R.inverse() * Hs;
		x += info.inverse() * (P0.inverse() * (prior - x) + Hs.transpose() * R.inverse() * nu);
		C = info.inverse();
	}
	Eigen::Vector3d mean;
	Eigen::Matrix3d cov;
	weightedMoments(f, mean, cov);
	for (int i = 0; i < 3; i++)
	{
		EXPECT_NEAR(mean[i], x[i], 0.1 * std::sqrt(C(i, i))) << i;
		EXPECT_NEAR(cov(i, i), C(i, i), 0.1 * C(i, i)) << i;
	}
	// Proposals that use the measurement make the weights more even than
	// the motion model alone does.
	std::printf("nominal %s, dual share %.1f: ESS %.2f\n",
		nominal == CMixtureProposal::Nominal::Motion ? "motion" : "optimal", phi, f.ESS());
	if (nominal == CMixtureProposal::Nominal::Motion && phi == 0)
	{
		EXPECT_LT(f.ESS(), 0.3);
	}
	else
	{
		EXPECT_GT(f.ESS(), 0.4);
	}
}

INSTANTIATE_TEST_SUITE_P(DualRatios, MixturePosterior,
	::testing::Combine(
		::testing::Values(CMixtureProposal::Nominal::Motion, CMixtureProposal::Nominal::Optimal),
		::testing::Values(0.0, 0.5, 1.0)));

TEST(CVSlamParticleFilter, OnlyTheObservedLandmarkIsUpdated)
{
	mrpt::random::getRandomGenerator().randomize(2);
	CVSlamParticleFilter f(manyParticles(100));
	std::vector<std::pair<LandmarkKey, LandmarkEstimate>> map;
	for (int i = 0; i < 300; i++)
		map.push_back({{LandmarkKind::Pose, i}, poseLandmark({i * 0.1, 1, 0}, 0.01)});
	f.setPriorMap(map);
	const LandmarkBank before = f.particle(0).bank;
	f.addOdometryIncrement({0.1, 0, 0});
	f.processFrame(frame(1, {poseMeasurement(7, se2::between({0.1, 0, 0}, {0.7, 1, 0}))}));
	for (size_t i = 0; i < f.particlesCount(); i++)
	{
		const LandmarkBank& bank = f.particle(i).bank;
		for (int k = 0; k < 300; k++)
		{
			if (k != 7)
			{
				EXPECT_EQ(bank[k].mean, before[k].mean);
			}
		}
		EXPECT_LT(bank[7].cov(0, 0), before[7].cov(0, 0));
		// Copy-on-write: only the path to slot 7 is new.
		EXPECT_EQ(bank.nodesNotIn(before), before.levels() + 1u);
	}
}

TEST(CVSlamParticleFilter, ResampledParticlesShareTheirBanks)
{
	mrpt::random::getRandomGenerator().randomize(4);
	CVSlamParticleFilter f(manyParticles(64));
	f.processFrame(frame(0, {}, {creation(1)}));
	for (size_t i = 0; i < 64; i++) f.setW(i, i == 5 ? 0.0 : -50.0);
	f.performResampling(f.options().pf.toMrpt());
	for (size_t i = 1; i < 64; i++)
		EXPECT_TRUE(f.particle(i).bank.sharesRootWith(f.particle(0).bank));
}

TEST(CVSlamParticleFilter, NewLandmarksStartFromEachParticlesOwnPose)
{
	auto o = spreadCloud(50, 0.5, 0.3, false);
	o.landmarks.init_std_xy = 0.01;
	mrpt::random::getRandomGenerator().randomize(6);
	CVSlamParticleFilter f(o);
	f.processFrame(frame(0, {}, {creation(42)}));
	ASSERT_TRUE(f.landmarkIndex().find({LandmarkKind::Pose, 42}));
	for (size_t i = 0; i < 50; i++)
	{
		const auto& l = f.particle(i).bank[0];
		EXPECT_TRUE(l.mean.isApprox(se2::toVector(f.particle(i).pose), 1e-12));
		EXPECT_NEAR(l.cov(0, 0), 0.01 * 0.01, 1e-12);
	}
	EXPECT_EQ(f.stats().landmarksCreated, 1u);
}

TEST(CVSlamParticleFilter, TheFirstLandmarkAnchorsTheMapAtTheCloudsMean)
{
	auto o = spreadCloud(500, 0.3, 0.2, true);
	o.motion.slip_probability = 0;
	mrpt::random::getRandomGenerator().randomize(8);
	CVSlamParticleFilter f(o);
	// No odometry pending: the mean is that of the initial cloud.
	const Eigen::Vector3d before = se2::toVector(f.meanPose());
	ASSERT_GT(f.poseCovariance()(2, 2), 0.02);  // a real spread to collapse
	f.processFrame(frame(1, {}, {creation(1)}));
	Eigen::Vector3d after;
	Eigen::Matrix3d spread;
	weightedMoments(f, after, spread);
	EXPECT_TRUE(after.isApprox(before, 1e-9));
	EXPECT_LT(spread.norm(), 1e-18);
	for (size_t i = 0; i < f.particlesCount(); i++)
		EXPECT_TRUE(f.particle(i).bank[0].mean.isApprox(after, 1e-9));

	// Later landmarks start from each particle's own pose again.
	for (int i = 0; i < 50; i++) f.addOdometryIncrement({0.02, 0, 0.01});
	f.processFrame(frame(2, {}, {creation(2)}));
	weightedMoments(f, after, spread);
	EXPECT_GT(spread(2, 2), 1e-4);
	for (size_t i = 0; i < f.particlesCount(); i++)
		EXPECT_TRUE(f.particle(i).bank[1].mean.isApprox(se2::toVector(f.particle(i).pose), 1e-12));
}

TEST(CVSlamParticleFilter, OdometryIsSampledOncePerAccumulatedIncrement)
{
	// 200 small increments then one update: the cloud's spread must be the
	// accumulated model covariance, not more.
	auto o = manyParticles(20000);
	o.motion.slip_probability = 0;
	o.landmarks.anchor_first_landmark = false;  // keep the sampled cloud
	mrpt::random::getRandomGenerator().randomize(7);
	CVSlamParticleFilter f(o);
	for (int i = 0; i < 100; i++) f.addOdometryIncrement({0.01, 0, 0.005});
	for (int i = 0; i < 100; i++) f.addOdometryIncrement({0.01, 0, -0.005});
	const MotionPrior mp(f.pendingOdometry(), CMotionModel(o.motion));
	const Eigen::Matrix3d expected = mp.globalCov({0, 0, 0});
	f.processFrame(frame(1, {}, {creation(1)}));  // samples the motion
	Eigen::Vector3d mean;
	Eigen::Matrix3d cov;
	weightedMoments(f, mean, cov);
	for (int i = 0; i < 3; i++) EXPECT_NEAR(cov(i, i), expected(i, i), 0.05 * expected(i, i));
	EXPECT_NEAR(mean[0], mp.increment().x, 0.01);
}

TEST(CVSlamParticleFilter, UnexplainedMeasurementsAreRejectedAndCounted)
{
	mrpt::random::getRandomGenerator().randomize(8);
	CVSlamParticleFilter f(manyParticles(100));
	f.setPriorMap({{{LandmarkKind::Pose, 1}, poseLandmark({2, 0, 0})}});
	const LandmarkBank before = f.particle(0).bank;
	// The landmark measured 3 m off: no particle explains it.
	f.processFrame(frame(1, {poseMeasurement(1, {-1, 0, 0})}));
	EXPECT_EQ(f.stats().rejectedUnexplained, 1u);
	EXPECT_EQ(f.stats().measurementsUsed, 0u);
	EXPECT_EQ(f.particle(0).bank[0].mean, before[0].mean);
	f.processFrame(frame(2, {poseMeasurement(1, {2, 0, 0})}));
	EXPECT_EQ(f.stats().measurementsUsed, 1u);
}

TEST(CVSlamParticleFilter, ALandmarkUnexplainedWhileLocalizedStaysWhereItIs)
{
	// Landmark 1 localizes the robot at the origin; landmark 2 is measured
	// every frame 1 m from where the map has it (a consistent false
	// recognition, or a moved object): every such measurement is rejected,
	// and neither the landmark nor the robot moves.
	auto o = manyParticles(100);
	mrpt::random::getRandomGenerator().randomize(13);
	CVSlamParticleFilter f(o);
	const se2::Pose l1{2, 0, 0}, mapped{0, 2, M_PI / 2}, measured{0, 3, M_PI / 2};
	f.setPriorMap({{{LandmarkKind::Pose, 1}, poseLandmark(l1)}, {{LandmarkKind::Pose, 2}, poseLandmark(mapped)}});
	for (int t = 1; t <= 5; t++)
	{
		f.processFrame(frame(t, {poseMeasurement(1, l1), poseMeasurement(2, measured)}));
		EXPECT_NEAR(f.particle(0).bank[1].mean.y(), mapped.y, 0.05) << "frame " << t;
	}
	EXPECT_EQ(f.stats().landmarksReinitialized, 0u);
	EXPECT_EQ(f.stats().rejectedUnexplained, 5u);
	EXPECT_NEAR(f.meanPose().y, 0, 0.05);
}

TEST(CVSlamParticleFilter, NonFiniteOdometryIsAnInputError)
{
	CVSlamParticleFilter f(manyParticles(10));
	EXPECT_THROW(f.addOdometryIncrement({std::nan(""), 0, 0}), InputError);
	EXPECT_THROW(f.addOdometryIncrement({0, 0, INFINITY}), InputError);
}

TEST(CVSlamParticleFilter, SameSeedSameResult)
{
	const auto runOnce = [] {
		mrpt::random::getRandomGenerator().randomize(10);
		CVSlamParticleFilter f(manyParticles(200));
		f.processFrame(frame(0, {}, {creation(1)}));
		for (int k = 1; k < 30; k++)
		{
			f.addOdometryIncrement({0.05, 0, 0.02});
			f.processFrame(frame(k, {poseMeasurement(1, se2::inverse({0.05 * k, 0, 0.02 * k}))}));
			if (f.ESS() < 0.5) f.performResampling(f.options().pf.toMrpt());
		}
		return f.meanPose();
	};
	const se2::Pose a = runOnce(), b = runOnce();
	EXPECT_EQ(a.x, b.x);
	EXPECT_EQ(a.y, b.y);
	EXPECT_EQ(a.phi, b.phi);
}

namespace
{
/** Drives a 4 m square whose odometry reports 5 deg too little per corner,
 * creates a landmark at each corner and measures the first again when it is
 * back (40 s later): the filter right after that loop closure. */
std::unique_ptr<CVSlamParticleFilter> filterAfterALoop(const CVSlamParticleFilter::TOptions& o)
{
	mrpt::random::getRandomGenerator().randomize(3);
	auto f = std::make_unique<CVSlamParticleFilter>(o);
	const double bias = 5 * M_PI / 180;
	f->processFrame(frame(0, {}, {creation(0)}));
	for (int corner = 1; corner <= 4; corner++)
	{
		for (int k = 0; k < 20; k++) f->addOdometryIncrement({0.2, 0, 0});
		for (int k = 0; k < 10; k++) f->addOdometryIncrement({0, 0, (M_PI / 2 - bias) / 10});
		const double t = 10.0 * corner;
		if (corner < 4)
		{
			f->processFrame(frame(t, {}, {creation(corner)}));
			if (f->ESS() < o.pf.BETA) f->performResampling(o.pf.toMrpt());
		}
		else
			f->processFrame(frame(t, {poseMeasurement(0, {0, 0, 0})}));
	}
	return f;
}

CVSlamParticleFilter::TOptions squareLoopOptions(bool loopClosure)
{
	auto o = manyParticles(200);
	o.loopClosure.enabled = loopClosure;
	o.motion.slip_probability = 0;
	return o;
}

/** The filter's position error of the landmark at the far corner after
 * filterAfterALoop. */
double farCornerErrorAfterALoop(bool loopClosure, TFilterStats& stats)
{
	const auto f = filterAfterALoop(squareLoopOptions(loopClosure));
	stats = f->stats();
	const auto slot = f->landmarkIndex().find({LandmarkKind::Pose, 2});
	const Eigen::Vector3d l = f->particle(f->bestParticleIndex()).bank[*slot].mean;
	return std::hypot(l[0] - 4, l[1] - 4);  // the far corner is at (4, 4)
}

/** The particles' weighted mean pose (the heading's by its sine and cosine). */
se2::Pose weightedMeanPose(const CVSlamParticleFilter& f)
{
	double sum = 0, x = 0, y = 0, c = 0, s = 0;
	for (size_t i = 0; i < f.particlesCount(); i++)
	{
		const double w = std::exp(f.getW(i));
		const se2::Pose& p = f.particle(i).pose;
		sum += w;
		x += w * p.x;
		y += w * p.y;
		c += w * std::cos(p.phi);
		s += w * std::sin(p.phi);
	}
	return {x / sum, y / sum, std::atan2(s, c)};
}

double poseDistance(const se2::Pose& a, const se2::Pose& b)
{
	return std::hypot(a.x - b.x, a.y - b.y) + std::abs(mrpt::math::wrapToPi(a.phi - b.phi));
}
}  // namespace

TEST(CVSlamParticleFilter, TheLoopClosureMovesTheCloudsMeanOntoTheSolutionsCurrentPose)
{
	const auto f = filterAfterALoop(squareLoopOptions(true));
	ASSERT_EQ(f->stats().loopClosures, 1u);
	const se2::Pose solution = f->loopClosureGraph()->keyframePath().back().second;
	const se2::Pose best = f->particle(f->bestParticleIndex()).pose;
	const se2::Pose mean = weightedMeanPose(*f);
	// The cloud's spread keeps the two apart, so only the mean sits on the
	// solution.
	ASSERT_GT(poseDistance(best, mean), 1e-3);
	EXPECT_LT(poseDistance(mean, solution), 1e-9);
	EXPECT_GT(poseDistance(best, solution), 1e-3);
}

TEST(CVSlamParticleFilter, ALoopClosureMovesTheMapOntoThePoseGraphSolution)
{
	TFilterStats without, with;
	const double before = farCornerErrorAfterALoop(false, without);
	const double after = farCornerErrorAfterALoop(true, with);
	EXPECT_EQ(without.loopClosures, 0u);
	EXPECT_EQ(with.loopClosures, 1u);
	// Dead reckoning puts the far corner 10 deg and about 0.7 m off; the
	// loop closure spreads the 20 deg over the whole square.
	EXPECT_GT(before, 0.4);
	EXPECT_LT(after, 0.5 * before);
}

TEST(CVSlamParticleFilter, AKidnapAnotherLandmarkContradictsIsUndone)
{
	auto o = manyParticles(300);
	o.kidnap.enabled = true;
	mrpt::random::getRandomGenerator().randomize(12);
	CVSlamParticleFilter f(o);
	const se2::Pose l1{2, 0, 0}, l2{0, 2, M_PI / 2}, elsewhere{-1, 0.5, 0.3};
	f.setPriorMap({{{LandmarkKind::Pose, 1}, poseLandmark(l1)},
				   {{LandmarkKind::Pose, 2}, poseLandmark(l2)}});
	// Landmark 1 recognized falsely but consistently, as if from elsewhere;
	// landmark 3 is created on the way, from the true pose (the origin).
	const auto falseZ = se2::between(elsewhere, l1);
	for (int t = 1; t <= 6; t++)
		f.processFrame(frame(t, {poseMeasurement(1, falseZ)}, t == 3 ? std::vector{creation(3)}
																	   : std::vector<LandmarkCreation>{}));
	ASSERT_EQ(f.stats().kidnapsDetected, 1u);
	ASSERT_NEAR(f.meanPose().x, elsewhere.x, 0.1);
	const auto& index = f.landmarkIndex();
	ASSERT_TRUE(index.entry(*index.find({LandmarkKind::Pose, 3})).suspect);
	f.processFrame(frame(6.5, {}, {creation(5)}));  // placed from the kidnapped cloud

	// Landmark 2 seen from the origin: only the cloud left behind explains it.
	f.processFrame(frame(7, {poseMeasurement(2, se2::between({0, 0, 0}, l2))}, {creation(4)}));
	EXPECT_EQ(f.stats().kidnapsReverted, 1u);
	EXPECT_TRUE(f.lastFrame().kidnapReverted);
	EXPECT_NEAR(f.meanPose().x, 0, 0.1);
	EXPECT_NEAR(f.meanPose().y, 0, 0.1);
	EXPECT_NEAR(f.meanPose().phi, 0, 0.05);
	// Placed from the true pose before the kidnap: sound again. Placed in
	// the frame that reverted: from the restored cloud, so sound too.
	EXPECT_FALSE(index.entry(*index.find({LandmarkKind::Pose, 3})).suspect);
	EXPECT_FALSE(index.entry(*index.find({LandmarkKind::Pose, 4})).suspect);
	EXPECT_TRUE(index.entry(*index.find({LandmarkKind::Pose, 5})).suspect);
}

namespace
{
/** n particles, odometry with a large turn noise, heading changes fused or
 * not; the random generator seeded. */
CVSlamParticleFilter::TOptions noisyTurns(size_t n, bool fuseHeadingChanges)
{
	auto o = manyParticles(n);
	o.motion.sigma_R = 0.1;
	o.headingChange.enabled = fuseHeadingChanges;
	mrpt::random::getRandomGenerator().randomize(5);
	return o;
}
}  // namespace

TEST(CVSlamParticleFilter, HeadingChangesCorrectTheOdometryTheParticlesAreDrawnFrom)
{
	// Odometry that turns 20% too much; every frame also brings the true
	// heading change since the last one, and no landmark is in view. With
	// the heading changes fused ([vslam_heading_change] enabled), the
	// estimate follows the true heading; without, the odometry's.
	for (const bool fuse : {false, true})
	{
		CVSlamParticleFilter f(noisyTurns(1000, fuse));
		se2::Pose truth{0, 0, 0};
		const se2::Pose trueStep{0.05, 0, 0.04}, reported{0.05, 0, 0.048};
		for (int k = 1; k <= 60; k++)
		{
			truth = se2::compose(truth, trueStep);
			f.addOdometryIncrement(reported);
			FrameMeasurements fr = frame(k, {});
			fr.headingChange = HeadingChangeMeasurement{
				mrpt::Clock::fromDouble(k - 1), mrpt::Clock::fromDouble(k), trueStep.phi, 1e-6};
			f.processFrame(fr);
		}
		const double headingError = std::abs(se2::wrap(f.meanPose().phi - truth.phi));
		// 60 x 0.008 rad = 27.5 deg of odometry error; fused, the first
		// frame has no reference yet (0.46 deg).
		if (fuse)
		{
			EXPECT_LT(headingError, 0.01);
			EXPECT_EQ(f.stats().headingChangesFused, 59u);
			EXPECT_EQ(f.stats().headingChangesWithoutReference, 1u);
			EXPECT_EQ(f.stats().headingChangesGated, 0u);
		}
		else
		{
			EXPECT_NEAR(headingError, 60 * 0.008, 1e-6);
			EXPECT_EQ(f.stats().headingChangesFused, 0u);
		}
	}
}

TEST(CVSlamParticleFilter, TimedOdometryLetsTheFirstImagesHeadingChangeBeFused)
{
	// Two odometry readings per image, turning 20% too much; the first image
	// (t = 1) brings no heading change, each later one the true change since
	// the image before. With the readings' times the change from the first
	// image is fused, and only the odometry before it stays in the heading;
	// without them the interval from the first image to the second is lost.
	const se2::Pose trueStep{0.05, 0, 0.04}, reported{0.05, 0, 0.048};
	const double errorPerReading = reported.phi - trueStep.phi;
	for (const bool timed : {false, true})
	{
		CVSlamParticleFilter f(noisyTurns(500, true));
		se2::Pose truth{0, 0, 0};
		for (int reading = 1; reading <= 40; reading++)
		{
			truth = se2::compose(truth, trueStep);
			const double t = 0.5 * reading;
			f.addOdometryIncrement(
				reported, timed ? std::optional(mrpt::Clock::fromDouble(t)) : std::nullopt);
			if (reading % 2 || reading == 2) continue;  // no image, or the first
			FrameMeasurements fr = frame(t, {});
			fr.headingChange = HeadingChangeMeasurement{
				mrpt::Clock::fromDouble(t - 1), mrpt::Clock::fromDouble(t), 2 * trueStep.phi, 1e-8};
			f.processFrame(fr);
		}
		const double headingError = se2::wrap(f.meanPose().phi - truth.phi);
		EXPECT_EQ(f.stats().headingChangesFused, timed ? 19u : 18u) << timed;
		EXPECT_EQ(f.stats().headingChangesWithoutReference, timed ? 0u : 1u) << timed;
		EXPECT_NEAR(headingError, (timed ? 2 : 4) * errorPerReading, 1e-3) << timed;
	}
}

TEST(CVSlamParticleFilter, AHeadingChangeAcrossAnUpdateIsFusedIntoWhatRemains)
{
	// A frame with a landmark measurement draws the particles and resets the
	// odometry at that image; the next heading change starts there and is
	// fused into the increment since. A measurement in a frame without a
	// heading change (another sensor) between two images leaves the next
	// heading change without its reference: not fused.
	auto o = manyParticles(200);
	o.headingChange.enabled = true;
	mrpt::random::getRandomGenerator().randomize(6);
	CVSlamParticleFilter f(o);
	f.setPriorMap({{{LandmarkKind::Pose, 1}, poseLandmark({2, 0, 0})}});
	auto withHeading = [](double t, std::vector<LandmarkMeasurement> ms) {
		FrameMeasurements fr = frame(t, std::move(ms));
		fr.headingChange = HeadingChangeMeasurement{
			mrpt::Clock::fromDouble(t - 1), mrpt::Clock::fromDouble(t), 0.0, 1e-6};
		return fr;
	};
	f.addOdometryIncrement({0.01, 0, 0});
	f.processFrame(withHeading(1, {poseMeasurement(1, {1.99, 0, 0})}));  // no reference yet
	f.addOdometryIncrement({0.01, 0, 0.02});
	f.processFrame(withHeading(2, {}));  // fused: the reference at 1 survived the update
	EXPECT_EQ(f.stats().headingChangesFused, 1u);
	EXPECT_NEAR(f.pendingOdometry().mean().phi, 0.0, 1e-4);
	f.addOdometryIncrement({0.01, 0, 0});
	f.processFrame(frame(2.5, {poseMeasurement(1, {1.97, 0, 0})}));  // another sensor: an update
	f.addOdometryIncrement({0.01, 0, 0});
	f.processFrame(withHeading(3, {}));
	EXPECT_EQ(f.stats().headingChangesFused, 1u);
	EXPECT_EQ(f.stats().headingChangesWithoutReference, 2u);
}

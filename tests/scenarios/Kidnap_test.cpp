/** Kidnapping (the scenario): the landmarks are already mapped
 * (3 cm / 1 deg map error), the robot localizes, and 30 s into the run it
 * is carried 3+ m away without odometry seeing it. Recovered means: within
 * 10 s of the kidnap the estimate comes within 0.3 m of the truth and stays
 * there for 5 s. With dual particles at least 19 of 20 seeds must recover;
 * without them (nominal particles only, no kidnap detection) the filter
 * must not. */
#include <gtest/gtest.h>
#include <libvslam/eval/KidnapRecovery.h>
#include <tests/support/ScenarioRunner.h>

using namespace vslam;

namespace
{
struct KidnapOutcome
{
	int recovered = 0;
	size_t kidnapsDetected = 0;
};

KidnapOutcome runKidnapSeeds(const CVSlamParticleFilter::TOptions& opts, const char* label)
{
	KidnapOutcome out;
	for (uint32_t seed = 1; seed <= 20; seed++)
	{
		CMeasurementSimulator::TOptions o;
		o.seed = seed;
		o.mapping_duration = 400;
		o.duration = 90;
		o.kidnap_times = {30};
		o.kidnap_min_distance = 3;
		const SimulatedRun run = CMeasurementSimulator(o).run();
		const auto map = vslam::testing::noisyPriorMap(run, 1000 + seed, 0.03, M_PI / 180);
		const auto r = vslam::testing::runScenario(run, opts, seed, map);
		if (r.kidnapIndices.size() != 1) ADD_FAILURE() << "seed " << seed << ": no kidnap simulated";
		if (r.kidnapIndices.empty()) continue;
		const size_t k = r.kidnapIndices.front();
		std::vector<double> times;
		for (size_t i = 0; i < r.filterError.size(); i++) times.push_back(double(i) * o.dt);
		const auto recovery = recoveryTime(times, r.filterError, times[k]);
		const double t = recovery.value_or(-1);
		const bool recovered = recovery && *recovery <= 10;
		out.recovered += recovered;
		out.kidnapsDetected += r.stats.kidnapsDetected;
		std::printf("%s seed %2u: error before %.2f m, after %.2f m, %s (%.1f s)\n", label, seed,
			r.filterError[k - 1], r.filterError[k], recovered ? "recovered" : "NOT recovered", t);
	}
	std::printf("%s: recovered %d/20, kidnaps detected %zu\n", label, out.recovered,
		out.kidnapsDetected);
	return out;
}
}  // namespace

TEST(Kidnap, DualParticlesRecoverInAtLeast19Of20Seeds)
{
	const KidnapOutcome o = runKidnapSeeds(CVSlamParticleFilter::TOptions(), "with duals");
	EXPECT_GE(o.recovered, 19);
	EXPECT_GE(o.kidnapsDetected, 19u);
}

TEST(Kidnap, WithoutDualParticlesTheFilterStaysLost)
{
	CVSlamParticleFilter::TOptions opts;
	opts.mixture.dual_ratio = 0;
	opts.mixture.dual_ratio_max = 0;
	opts.kidnap.enabled = false;
	const KidnapOutcome o = runKidnapSeeds(opts, "nominal only");
	// Measured: 0/20. Nominal particles can only reach the new place by
	// motion noise, so recovery within 10 s stays the exception.
	EXPECT_LE(o.recovered, 5);
	EXPECT_EQ(o.kidnapsDetected, 0u);
}

/** Global localization: the robot starts somewhere unknown in a mapped
 * home (3 cm / 1 deg map error) and must find itself from the first
 * recognitions: within 0.3 m of the truth (and staying there for 5 s) at
 * most 10 s after it first measures a mapped landmark, in at least 19 of 20
 * seeds, and never lock on to a wrong pose (declared found more than 1 m
 * from the truth). */
TEST(Kidnap, FromAnUnknownStartTheRobotFindsItselfInAtLeast19Of20Seeds)
{
	int found = 0, wrongLockOns = 0;
	for (uint32_t seed = 1; seed <= 20; seed++)
	{
		CMeasurementSimulator::TOptions o;
		o.seed = seed;
		o.mapping_duration = 400;
		o.duration = 60;
		o.kidnap_times = {};
		const SimulatedRun run = CMeasurementSimulator(o).run();
		const auto map = vslam::testing::noisyPriorMap(run, 1000 + seed, 0.03, M_PI / 180);
		const auto r =
			vslam::testing::runScenario(run, CVSlamParticleFilter::TOptions(), seed, map, vslam::testing::StartPose::Unknown);
		const auto first = std::find(r.mappedLandmarkMeasured.begin(), r.mappedLandmarkMeasured.end(), 1);
		const auto known = std::find(r.poseKnown.begin(), r.poseKnown.end(), 1);
		if (first == r.mappedLandmarkMeasured.end() || known == r.poseKnown.end())
		{
			std::printf("unknown start, seed %2u: %s\n", seed, first == r.mappedLandmarkMeasured.end() ? "no mapped landmark measured" : "never found");
			continue;
		}
		std::vector<double> times;
		for (size_t i = 0; i < r.filterError.size(); i++) times.push_back(double(i) * o.dt);
		const size_t firstAt = static_cast<size_t>(first - r.mappedLandmarkMeasured.begin());
		const size_t knownAt = static_cast<size_t>(known - r.poseKnown.begin());
		const auto recovery = recoveryTime(times, r.filterError, times[firstAt]);
		found += recovery && *recovery <= 10;
		wrongLockOns += r.filterError[knownAt] > 1.0;
		std::printf("unknown start, seed %2u: first mapped landmark at %.1f s, found at %.1f s (error %.2f m), "
					"within 0.3 m %.1f s after the first\n",
			seed, times[firstAt], times[knownAt], r.filterError[knownAt], recovery.value_or(-1));
	}
	std::printf("unknown start: found %d/20, wrong lock-ons %d\n", found, wrongLockOns);
	EXPECT_GE(found, 19);
	EXPECT_EQ(wrongLockOns, 0);
}

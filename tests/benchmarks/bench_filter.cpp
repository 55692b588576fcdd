/** Filter update throughput (Google Benchmark): one update = the odometry
 * increment since the previous image plus one visual measurement of a
 * mapped landmark, processed by every particle (proposal, weights, the
 * landmark's Kalman update) and resampling when ESS < BETA, as
 * CParticleFilter::executeOn does. The map of L landmarks is given as a
 * shared prior (map continuation), so banks diverge only through updates.
 *
 *   bench_filter --benchmark_filter='Update/optimal_nominal/200/1000$'
 * Counters: updates/s (items_per_second), peak_MiB (process peak so far:
 * run one configuration per process for per-configuration memory, as
 * scripts/run_benchmarks.sh does). The motion_nominal variant uses the
 * paper's nominal proposal (motion model only). */
#include <benchmark/benchmark.h>
#include <libvslam/app/RunSummary.h>
#include <libvslam/filter/CVSlamParticleFilter.h>
#include <mrpt/random/RandomGenerators.h>

using namespace vslam;

namespace
{
void Update(benchmark::State& state, CMixtureProposal::Nominal nominal)
{
	const auto particles = static_cast<uint32_t>(state.range(0));
	const auto landmarks = static_cast<size_t>(state.range(1));
	mrpt::random::getRandomGenerator().randomize(1);
	CVSlamParticleFilter::TOptions o;
	o.pf.sampleSize = particles;
	o.mixture.nominal_proposal = nominal;
	CVSlamParticleFilter filter(o);

	// Landmarks on a 1 m grid; the robot drives among them.
	std::vector<std::pair<LandmarkKey, LandmarkEstimate>> map;
	const size_t side = static_cast<size_t>(std::ceil(std::sqrt(double(landmarks))));
	for (size_t i = 0; i < landmarks; i++)
	{
		LandmarkEstimate l;
		l.kind = LandmarkKind::Pose;
		l.mean << double(i % side), double(i / side), 0.0;
		l.cov = Eigen::Matrix3d::Identity() * 1e-3;
		map.push_back({{LandmarkKind::Pose, int64_t(i)}, l});
	}
	filter.setPriorMap(map);

	mrpt::random::CRandomGenerator rng(2);
	se2::Pose truth{0, 0, 0};
	const auto pfOptions = o.pf.toMrpt();
	double t = 1.7e9;
	for (auto _ : state)
	{
		const se2::Pose u{0.05, 0, 0.01};
		truth = se2::compose(truth, u);
		filter.addOdometryIncrement(u);
		const size_t id = rng.drawUniform32bit() % landmarks;
		const se2::Pose z = se2::between(truth, {double(id % side), double(id / side), 0.0});
		LandmarkMeasurement m;
		m.key = {LandmarkKind::Pose, int64_t(id)};
		m.z.resize(3);
		m.z << z.x + 0.02 * rng.drawGaussian1D_normalized(),
			z.y + 0.02 * rng.drawGaussian1D_normalized(), z.phi;
		m.R = MatN::Zero(3, 3);
		m.R.diagonal() << 0.0081, 0.0081, 0.0019;
		FrameMeasurements f;
		f.timestamp = mrpt::Clock::fromDouble(t += 0.5);
		f.measurements = {m};
		filter.processFrame(f);
		filter.normalizeWeights();
		if (filter.ESS() < pfOptions.BETA) filter.performResampling(pfOptions);
	}
	state.SetItemsProcessed(state.iterations());
	state.counters["peak_MiB"] = peakMemoryMiB();
	state.counters["resamplings_per_update"] =
		double(filter.stats().resamplings) / double(std::max<int64_t>(1, state.iterations()));
}
}  // namespace

BENCHMARK_CAPTURE(Update, optimal_nominal, CMixtureProposal::Nominal::Optimal)
	->ArgsProduct({{100, 200, 500, 1000, 2000}, {10, 100, 1000, 10000, 100000}})
	->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(Update, motion_nominal, CMixtureProposal::Nominal::Motion)
	->ArgsProduct({{200, 1000}, {1000, 100000}})
	->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();

/** Time of one solve of the loop-closure pose graph against its size: a
 * robot drives laps of a 10 m x 10 m square past 16 range-bearing beacons
 * (MRCLAM's arena has 15), measuring those within 4 m at every keyframe,
 * with odometry that turns 2% short; the graph is solved every 50
 * keyframes on the way, as a run's loop closures do. Then:
 *  - After50: 50 more keyframes (with their measurements), solved;
 *  - After1: one more keyframe, solved: the common case.
 * Counters: nodes, edges, Levenberg-Marquardt iterations of the solve. */
#include <benchmark/benchmark.h>
#include <libvslam/graph/CLandmarkPoseGraph.h>

#include <cmath>

using namespace vslam;

namespace
{
LandmarkMeasurement rangeBearing(const se2::Pose& robot, int64_t id, double px, double py)
{
	LandmarkMeasurement m;
	m.key = {LandmarkKind::Point, id};
	m.z.resize(2);
	m.z << std::hypot(px - robot.x, py - robot.y), se2::wrap(std::atan2(py - robot.y, px - robot.x) - robot.phi);
	m.R = MatN::Zero(2, 2);
	m.R.diagonal() << 0.1 * 0.1, std::pow(1.0 * M_PI / 180, 2);
	return m;
}

/** Drives the laps, one keyframe per call of next(). */
struct SquareLaps
{
	CLandmarkPoseGraph graph{noThinning(), {0, 0, 0}};
	std::vector<std::pair<double, double>> beacons;
	std::vector<bool> placed;
	se2::Pose truth{0, 0, 0}, guess{0, 0, 0};
	int k = 0;

	static CLandmarkPoseGraph::TOptions noThinning()
	{
		CLandmarkPoseGraph::TOptions o;
		o.max_keyframes = 0;
		return o;
	}

	SquareLaps()
	{
		for (int i = 0; i < 4; i++)
			for (int j = 0; j < 4; j++) beacons.emplace_back(-1 + 4 * i, -1 + 4 * j);
		placed.assign(beacons.size(), false);
	}

	void next()
	{
		// 0.5 m per keyframe, a 90 degree turn every 21 keyframes.
		const bool corner = k % 21 == 20;
		const se2::Pose u = corner ? se2::Pose{0, 0, M_PI / 2} : se2::Pose{0.5, 0, 0};
		const se2::Pose reported = corner ? se2::Pose{0, 0, 0.98 * M_PI / 2} : u;
		truth = se2::compose(truth, u);
		guess = se2::compose(guess, reported);
		graph.addOdometry(reported,
			Eigen::Vector3d(0.02 * 0.02, 0.02 * 0.02, std::pow(1.0 * M_PI / 180, 2)).asDiagonal());
		graph.addKeyframe(mrpt::Clock::time_point() + std::chrono::seconds(k++), guess);
		for (size_t b = 0; b < beacons.size(); b++)
		{
			const auto [px, py] = beacons[b];
			if (std::hypot(px - truth.x, py - truth.y) > 4) continue;
			const auto m = rangeBearing(truth, static_cast<int64_t>(b), px, py);
			if (placed[b])
				graph.addMeasurement(b, m);
			else
				graph.placeLandmark(b, m), placed[b] = true;
		}
	}
};

void count(benchmark::State& state, const CLandmarkPoseGraph& graph, size_t iterations)
{
	state.counters["nodes"] = static_cast<double>(graph.nodes());
	state.counters["edges"] = static_cast<double>(graph.edges());
	state.counters["iterations"] = static_cast<double>(iterations);
}

/** Drives `keyframes` keyframes, solving every 50. */
SquareLaps drive(int keyframes)
{
	SquareLaps laps;
	while (laps.k < keyframes)
	{
		laps.next();
		if (laps.k % 50 == 0) laps.graph.optimize();
	}
	return laps;
}

void SolveAfter(benchmark::State& state, int added)
{
	const SquareLaps laps = drive(static_cast<int>(state.range(0)));
	size_t iterations = 0;
	for (auto _ : state)
	{
		state.PauseTiming();
		SquareLaps more = laps;
		for (int i = 0; i < added; i++) more.next();
		state.ResumeTiming();
		iterations = more.graph.optimize().iterations;
	}
	count(state, laps.graph, iterations);
}

void After50(benchmark::State& state) { SolveAfter(state, 50); }
void After1(benchmark::State& state) { SolveAfter(state, 1); }
}  // namespace

BENCHMARK(After50)->Arg(250)->Arg(500)->Arg(1000)->Arg(2000)->Arg(4000)->Unit(benchmark::kMillisecond);
BENCHMARK(After1)->Arg(250)->Arg(500)->Arg(1000)->Arg(2000)->Arg(4000)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();

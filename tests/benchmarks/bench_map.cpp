/** The saved map (final_map.vslam, Google Benchmark): writing it, reading
 * it, and loading it into a front-end (the landmark database and its
 * search index), for maps of L visual landmarks of 40 points each with
 * SIFT-like descriptors in the default storage (uint8):
 *
 *   bench_map [--benchmark_filter='Load/10000']
 *
 * Counters: bytes_per_landmark (the file's size over L). */
#include <benchmark/benchmark.h>
#include <libvslam/frontend/CVisualFrontEnd.h>
#include <libvslam/io/VSlamMapFile.h>

#include <filesystem>
#include <random>

using namespace vslam;
namespace fs = std::filesystem;

namespace
{
constexpr int kPointsPerLandmark = 40;

/** A map of `landmarks` visual landmarks on a 50 m x 50 m floor. */
CVSlamMap syntheticMap(int landmarks)
{
	std::mt19937 rng(1);
	std::uniform_real_distribution<float> coordinate(-1.5f, 1.5f), depth(1.0f, 5.0f), place(0, 50);
	std::uniform_int_distribution<int> siftValue(0, 160);
	CVSlamMap map;
	map.descriptorStorage = "uint8";
	map.nextVisualLandmarkId = landmarks + 1;
	for (int id = 1; id <= landmarks; id++)
	{
		CVSlamMap::TLandmarkEstimate e;
		e.id = id;
		e.mean = {place(rng), place(rng), 0.5};
		e.cov = {0.01, 0, 0, 0.01, 0, 0.001};
		map.estimates.push_back(e);
		CVSlamMap::TLandmarkAppearance a;
		a.id = id;
		a.descriptorCols = 128;
		for (int p = 0; p < kPointsPerLandmark; p++)
		{
			a.points.push_back({depth(rng), coordinate(rng), coordinate(rng)});
			a.depthStd.push_back(0.05f);
			for (int c = 0; c < 128; c++) a.descriptorBytes.push_back(static_cast<uint8_t>(siftValue(rng)));
		}
		map.appearances.push_back(std::move(a));
	}
	return map;
}

std::string mapFile(int landmarks)
{
	return (fs::temp_directory_path() / ("bench_map_" + std::to_string(landmarks) + ".vslam")).string();
}

void Write(benchmark::State& state)
{
	const int landmarks = static_cast<int>(state.range(0));
	const CVSlamMap map = syntheticMap(landmarks);
	for (auto _ : state) writeVSlamMap(mapFile(landmarks), map);
	state.counters["bytes_per_landmark"] = static_cast<double>(fs::file_size(mapFile(landmarks))) / landmarks;
}

void Read(benchmark::State& state)
{
	const int landmarks = static_cast<int>(state.range(0));
	writeVSlamMap(mapFile(landmarks), syntheticMap(landmarks));
	for (auto _ : state) benchmark::DoNotOptimize(readVSlamMap(mapFile(landmarks)));
}

/** Read, then into a front-end: what a run does before its first image. */
void Load(benchmark::State& state)
{
	const int landmarks = static_cast<int>(state.range(0));
	writeVSlamMap(mapFile(landmarks), syntheticMap(landmarks));
	for (auto _ : state)
	{
		CVisualFrontEnd frontEnd{CVisualFrontEnd::TOptions()};
		frontEnd.loadMap(readVSlamMap(mapFile(landmarks)), mrpt::poses::CPose2D());
		benchmark::DoNotOptimize(frontEnd.database().size());
	}
	fs::remove(mapFile(landmarks));
}
}  // namespace

BENCHMARK(Write)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(Read)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(Load)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();

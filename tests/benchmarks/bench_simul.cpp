/** vslam-simul's costs: one rendered camera frame (MRPT CFBORender on
 * Mesa's software rasterizer, distortion, image defects) at 320x240 and
 * 640x480 in the apartment, and one laser scan (181 rays) there.
 *   build/bin/bench_simul
 */
#include <benchmark/benchmark.h>
#include <libvslam/sim/CameraImaging.h>
#include <libvslam/sim/CameraRenderer.h>
#include <libvslam/sim/CVisualSimulator.h>
#include <libvslam/world/FloorPlanFile.h>
#include <libvslam/world/LaserRayCaster.h>
#include <libvslam/world/WorldScene.h>

#include <cmath>

using namespace vslam;

namespace
{
const world::FloorPlan& apartment()
{
	static const world::FloorPlan plan =
		world::loadFloorPlan(std::string(VSLAM_SOURCE_DIR) + "/config_ini/worlds/apartment.world", "/usr/share");
	return plan;
}

void BM_RenderFrame(benchmark::State& state)
{
	const int width = static_cast<int>(state.range(0)), height = width * 3 / 4;
	const bool distorted = state.range(1) != 0;
	world::WorldScene scene(apartment(), 0, CVisualSimulator::TOptions().texture_max_side);
	mrpt::img::TCamera cam;
	cam.ncols = width, cam.nrows = height;
	cam.setIntrinsicParamsFromValues(0.78 * width, 0.78 * width, width / 2.0 - 0.5, height / 2.0 - 0.5);
	cam.dist.fill(0);
	if (distorted) cam.dist[0] = -0.2, cam.dist[1] = 0.05;
	CameraRenderer renderer(cam);
	const mrpt::poses::CPose3D mount = CVisualSimulator::TOptions().cameraPoseOnRobot();
	CameraImaging imaging(TCameraImagingOptions(), cam.fx(), 1);
	FrameConditions frame;
	frame.turnRate = 0.3;
	int k = 0;
	for (auto _ : state)
	{
		// Drive along the living room, turning: a new view every frame.
		const double a = 0.05 * k++;
		const mrpt::poses::CPose3D robot(2.0 + 1.5 * std::cos(a), 2.0 + 0.8 * std::sin(a), 0, a + M_PI / 2, 0, 0);
		cv::Mat img = renderer.render(scene.scene(), robot + mount);
		frame.noiseSeed = static_cast<uint64_t>(k);
		imaging.capture(img, frame);
		benchmark::DoNotOptimize(img.data);
	}
	state.counters["frames_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RenderFrame)->Args({320, 0})->Args({640, 0})->Args({640, 1})->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_LaserScan(benchmark::State& state)
{
	const auto segments = apartment().obstacleSegments();
	int k = 0;
	double sum = 0;
	for (auto _ : state)
	{
		const Eigen::Vector2d origin(2.0 + 0.001 * (k++ % 1000), 2.0);
		for (int i = 0; i < 181; i++)
		{
			const double a = M_PI * i / 180;
			sum += world::castRay(segments, {}, origin, {std::cos(a), std::sin(a)});
		}
	}
	benchmark::DoNotOptimize(sum);
}
BENCHMARK(BM_LaserScan)->Unit(benchmark::kMicrosecond);
}  // namespace

BENCHMARK_MAIN();

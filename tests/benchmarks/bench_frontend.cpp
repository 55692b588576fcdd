/** Visual front-end speed (Google Benchmark): one camera image end to end
 * (SIFT features, encoding, the database search, PnP on the candidates)
 * against a database of L landmarks, at 320x240 and 640x480.
 *
 * The database holds one true landmark of the scene in view, built by the
 * front-end's own creation from three rendered views (tests/support/
 * RoomRenderer.h), and L-1 others made of real SIFT descriptors from
 * renderings of other rooms (rows drawn from a pool, with noise) at random
 * 3-D points, so the search meets realistic descriptors everywhere.
 *
 *   bench_frontend --benchmark_filter='Frame/640/1000/' [--set SECTION.KEY=VALUE ...]
 * Counters: frames/s (items_per_second) and ms per stage: features_ms,
 * search_ms, pose_ms, and heading_ms (the heading change from a view 6 cm
 * back and 2 deg turned; none with --set vslam_heading_measurement.enabled=false);
 * bytes_per_landmark (points + stored descriptors) and
 * index_bytes_per_landmark.
 *
 * Also the descriptor matching of the pose stage alone, ours against
 * OpenCV's brute-force matcher (the one it replaced), on a x b random
 * SIFT-sized descriptors:
 *   bench_frontend --benchmark_filter='Match'
 * and the search codec's projection, ours against cv::gemm (which calls the
 * system's BLAS):
 *   bench_frontend --benchmark_filter='Project'  */
#include <benchmark/benchmark.h>
#include <libvslam/config/Overrides.h>
#include <libvslam/frontend/CLandmarkDatabase.h>
#include <libvslam/frontend/CVisualFrontEnd.h>
#include <libvslam/frontend/DescriptorCodec.h>
#include <libvslam/frontend/DescriptorMatching.h>
#include <libvslam/frontend/HeadingChange.h>
#include <libvslam/frontend/ImageBufferAllocation.h>
#include <libvslam/frontend/LandmarkCreator.h>
#include <libvslam/frontend/LandmarkRecognizer.h>
#include <tests/support/RoomRenderer.h>

#include <opencv2/features2d.hpp>

#include <chrono>
#include <random>

using namespace vslam;

namespace
{
constexpr double kDeg = M_PI / 180;
const mrpt::poses::CPose3D kMount(0.1, 0, 0.3, -90 * kDeg, 0, -90 * kDeg);

mrpt::img::TCamera camera(int width)
{
	mrpt::img::TCamera c;
	c.ncols = width;
	c.nrows = width * 3 / 4;
	c.setIntrinsicParamsFromValues(0.8 * width, 0.8 * width, width / 2.0, width * 3 / 8.0);
	return c;
}

std::vector<vslam::config::Override> gOverrides;

CVisualFrontEnd::TOptions benchOptions() { return loadFrontEndOptions("", gOverrides); }

struct Scene
{
	CVisualFrontEnd::TOptions options = benchOptions();
	CFeatureExtractor extractor{options.features};
	CImageCalibration calibration;
	cv::Mat query;  //!< the image every iteration processes
	ImageFeatures previous;  //!< the view before it, for the heading change
	double chord = 0;  //!< m between the two
	std::unique_ptr<CLandmarkDatabase> database;
};

std::unique_ptr<Scene> makeScene(int width, int landmarks)
{
	auto s = std::make_unique<Scene>();
	const auto cam = camera(width);
	s->calibration = CImageCalibration::from(cam, cam.ncols, cam.nrows, s->options.camera, "bench");
	s->database = std::make_unique<CLandmarkDatabase>(s->options.database, s->options.features.match_ratio);
	const vslam::testing::RoomRenderer room(5.0, 4.0, 2.5, 42);
	const auto render = [&](const vslam::testing::RoomRenderer& r, const mrpt::poses::CPose2D& p) {
		return r.render(cam, mrpt::poses::CPose3D(p) + kMount);
	};
	// The true landmark: three views 0.2 m apart.
	std::vector<CreationView> views(3);
	for (int i = 0; i < 3; i++)
	{
		const mrpt::poses::CPose2D p(1.0 + 0.2 * i, 2.0, 0);
		views[i].features = s->extractor.extract(render(room, p), s->calibration);
		views[i].cameraPose = mrpt::poses::CPose3D(p) + kMount;
	}
	auto created = s->options.creator().create({&views[0], &views[1], &views[2]}, kMount);
	if (!created.landmark) throw std::runtime_error("bench: no landmark: " + created.why);
	created.landmark->id = 0;
	s->database->insert(*created.landmark);
	const mrpt::poses::CPose2D queryPose(1.6, 2.2, -5 * kDeg), previousPose(1.54, 2.2, -3 * kDeg);
	s->query = render(room, queryPose);
	s->previous = s->extractor.extract(render(room, previousPose), s->calibration);
	s->chord = (queryPose - previousPose).norm();

	// Others: real descriptors from other rooms, random points.
	cv::Mat pool;
	for (uint32_t seed = 1; pool.rows < 20000 && seed < 40; seed++)
	{
		const vslam::testing::RoomRenderer other(5.0, 4.0, 2.5, 1000 + seed);
		for (double a : {0.0, 1.6, 3.2, 4.8})
			pool.push_back(s->extractor.extract(render(other, mrpt::poses::CPose2D(2.5, 2.0, a)), s->calibration).descriptors);
	}
	std::mt19937 rng(7);
	std::uniform_int_distribution<int> row(0, pool.rows - 1);
	std::normal_distribution<float> g;
	const int points = static_cast<int>(created.landmark->points.size());
	for (int id = 1; id < landmarks; id++)
	{
		VisualLandmarkModel lm;
		lm.id = id;
		lm.descriptors = cv::Mat(points, 128, CV_32F);
		for (int r = 0; r < points; r++)
		{
			pool.row(row(rng)).copyTo(lm.descriptors.row(r));
			for (int d = 0; d < 128; d++)
				lm.descriptors.at<float>(r, d) = std::max(0.0f, lm.descriptors.at<float>(r, d) + 3 * g(rng));
			lm.points.emplace_back(2 + g(rng), g(rng), g(rng));
		}
		s->database->insert(std::move(lm));
	}
	return s;
}

double ms(std::chrono::steady_clock::time_point since)
{
	return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

void Frame(benchmark::State& state)
{
	const int width = static_cast<int>(state.range(0));
	const int landmarks = static_cast<int>(state.range(1));
	const auto scene = makeScene(width, landmarks);
	double features = 0, search = 0, pose = 0, heading = 0;
	size_t recognized = 0, headingChanges = 0;
	const CLandmarkRecognizer recognizer = scene->options.recognizer();
	const CHeadingChangeEstimator headingEstimator = scene->options.headingEstimator();
	for (auto _ : state)
	{
		auto t = std::chrono::steady_clock::now();
		ImageFeatures f = scene->extractor.extract(scene->query, scene->calibration);
		scene->database->encode(f);
		features += ms(t);
		t = std::chrono::steady_clock::now();
		const auto candidates = scene->database->candidates(f);
		search += ms(t);
		t = std::chrono::steady_clock::now();
		for (const auto& c : candidates)
			if (recognizer.recognize(f, *scene->database->find(c.id), kMount)) recognized++;
		pose += ms(t);
		if (scene->options.heading.enabled)
		{
			t = std::chrono::steady_clock::now();
			if (headingEstimator.estimate(scene->previous, f, kMount, scene->chord))
				headingChanges++;
			heading += ms(t);
		}
	}
	const double n = static_cast<double>(state.iterations());
	state.SetItemsProcessed(state.iterations());
	state.counters["features_ms"] = features / n;
	state.counters["search_ms"] = search / n;
	state.counters["pose_ms"] = pose / n;
	if (scene->options.heading.enabled)
	{
		state.counters["heading_ms"] = heading / n;
		state.counters["heading_changes_per_frame"] = headingChanges / n;
	}
	state.counters["recognized_per_frame"] = recognized / n;
	state.counters["bytes_per_landmark"] = double(scene->database->landmarkBytes()) / landmarks;
	state.counters["index_bytes_per_landmark"] = double(scene->database->indexBytes()) / landmarks;
}
/** Random descriptors in SIFT's value range, a fixed seed. */
cv::Mat randomDescriptors(int rows, uint64_t seed)
{
	cv::Mat d(rows, 128, CV_32F);
	cv::RNG(seed).fill(d, cv::RNG::UNIFORM, 0, 150);
	return d;
}

void MatchDescriptors(benchmark::State& state)
{
	const cv::Mat a = randomDescriptors(static_cast<int>(state.range(0)), 1);
	const cv::Mat b = randomDescriptors(static_cast<int>(state.range(1)), 2);
	for (auto _ : state) benchmark::DoNotOptimize(matchDescriptors(a, b, 0.8));
}

void MatchDescriptorsOpenCvBruteForce(benchmark::State& state)
{
	const cv::Mat a = randomDescriptors(static_cast<int>(state.range(0)), 1);
	const cv::Mat b = randomDescriptors(static_cast<int>(state.range(1)), 2);
	for (auto _ : state)
	{
		std::vector<std::vector<cv::DMatch>> knn;
		cv::BFMatcher(cv::NORM_L2).knnMatch(a, b, knn, 2);
		benchmark::DoNotOptimize(knn);
	}
}

/** The search codec's 16-D projection of one image's descriptors (the
 * database search's first step), ours against the cv::gemm it replaced. */
void ProjectDescriptors(benchmark::State& state)
{
	const DescriptorCodec codec(DescriptorCodec::Kind::Projected, 16);
	const cv::Mat d = randomDescriptors(static_cast<int>(state.range(0)), 1);
	for (auto _ : state) benchmark::DoNotOptimize(codec.encode(d));
}

void ProjectDescriptorsOpenCvGemm(benchmark::State& state)
{
	const cv::Mat d = randomDescriptors(static_cast<int>(state.range(0)), 1);
	const cv::Mat projection = randomDescriptors(16, 2);
	for (auto _ : state)
	{
		const cv::Mat projected = d * projection.t();
		benchmark::DoNotOptimize(projected.data);
	}
}
}  // namespace

BENCHMARK(ProjectDescriptors)->Arg(600)->Unit(benchmark::kMicrosecond);
BENCHMARK(ProjectDescriptorsOpenCvGemm)->Arg(600)->Unit(benchmark::kMicrosecond);
BENCHMARK(MatchDescriptors)->Args({600, 300})->Args({600, 600})->Unit(benchmark::kMillisecond);
BENCHMARK(MatchDescriptorsOpenCvBruteForce)->Args({600, 300})->Args({600, 600})->Unit(benchmark::kMillisecond);

BENCHMARK(Frame)
	->ArgsProduct({{320, 640}, {10, 100, 1000, 5000}})
	->Unit(benchmark::kMillisecond)
	->MinTime(2.0);

int main(int argc, char** argv)
{
	vslam::keepImageBuffersInTheProcess();  // as the apps that run the front-end
	// --set SECTION.KEY=VALUE (repeatable) before the benchmark's own flags.
	std::vector<char*> rest{argv[0]};
	for (int i = 1; i < argc; i++)
	{
		if (std::string(argv[i]) == "--set" && i + 1 < argc)
			gOverrides.push_back(vslam::config::parseOverride(argv[++i]));
		else
			rest.push_back(argv[i]);
	}
	int n = static_cast<int>(rest.size());
	benchmark::Initialize(&n, rest.data());
	benchmark::RunSpecifiedBenchmarks();
	benchmark::Shutdown();
	return 0;
}

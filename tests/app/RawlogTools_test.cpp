/** Stock MRPT tools read rawlogs with vslam's observation types once the
 * shared library that registers them is preloaded; and the other apps
 * (simulator, evaluator) behave as documented. */
#include <gtest/gtest.h>
#include <tests/support/RunCommand.h>
#include <tests/support/TempDir.h>

#include <filesystem>

using vslam::testing::readFile;
using vslam::testing::contains;
using vslam::testing::runCommand;
using vslam::testing::TempDir;
namespace fs = std::filesystem;

namespace
{
const std::string kSource = VSLAM_SOURCE_DIR;
const std::string kBin = std::string(VSLAM_BINARY_DIR) + "/bin/";
const std::string kObsLib = std::string(VSLAM_BINARY_DIR) + "/lib/libvslam_obs.so";
/** What to preload so a stock MRPT tool loads our library: in a sanitized
 * build the sanitizer runtime must come first (and the tool's own leaks,
 * not ours, are not reported). */
const std::string kPreload = std::string(VSLAM_SANITIZER_RUNTIME).empty()
	? "LD_PRELOAD='" + kObsLib + "' "
	: "ASAN_OPTIONS=detect_leaks=0 LD_PRELOAD='" + std::string(VSLAM_SANITIZER_RUNTIME) + " " +
		kObsLib + "' ";
const std::string kDemoRawlog = kSource + "/rawlogs/demo_visual.rawlog";


std::string rawlogEdit()
{
	for (const char* p : {"/usr/bin/rawlog-edit", "/usr/local/bin/rawlog-edit"})
		if (fs::exists(p)) return p;
	return "";
}
}  // namespace

TEST(RawlogTools, RawlogEditListsEveryObjectWithThePreloadedLibrary)
{
	const std::string tool = rawlogEdit();
	if (tool.empty()) GTEST_SKIP() << "rawlog-edit not installed (package mrpt-apps)";
	const auto r = runCommand(kPreload + tool + " --info -i '" +
		kDemoRawlog + "'");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	// 3000 (action, sensory frame) pairs; the camera's observations by label.
	EXPECT_TRUE(contains(r.output, "Overall number of objects         : 6000")) << r.output;
	EXPECT_TRUE(contains(r.output, "CAMERA")) << r.output;
	// Without the library MRPT cannot read the frames holding them.
	const auto without = runCommand(tool + " --info -i '" + kDemoRawlog + "'");
	EXPECT_FALSE(without.exitCode == 0 && contains(without.output, "CAMERA")) << without.output;
}

TEST(RawlogTools, RawlogEditExportsTheMeasurementColumns)
{
	const std::string tool = rawlogEdit();
	if (tool.empty()) GTEST_SKIP() << "rawlog-edit not installed (package mrpt-apps)";
	TempDir dir;
	fs::copy_file(kDemoRawlog, dir.file("demo.rawlog"));
	const auto r = runCommand("cd '" + dir.path().string() + "' && " + kPreload + tool + " --export-txt -i demo.rawlog");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	// One file per sensor label, each with its own column header.
	const std::string measurements = readFile(dir.file("demo_CAMERA.txt"));
	const std::string created = readFile(dir.file("demo_CAMERA_NEW_LANDMARK.txt"));
	ASSERT_FALSE(measurements.empty()) << r.output;
	ASSERT_FALSE(created.empty()) << r.output;
	EXPECT_TRUE(contains(measurements.substr(0, measurements.find('\n')), "ProjErrRMS"))
		<< measurements.substr(0, 300);
	EXPECT_TRUE(contains(created.substr(0, created.find('\n')), "NViews")) << created.substr(0, 300);
	EXPECT_EQ(std::count(measurements.begin(), measurements.end(), '\n'), 380 + 1);
}

TEST(RawlogTools, SimulatorIsReproducibleAndEvaluatorScoresItsTruth)
{
	TempDir dir;
	const std::string sim = kBin + "vslam-simul-measurements '" + kSource +
		"/config_ini/simul_range_bearing.ini' ";
	ASSERT_EQ(runCommand(sim + "'" + dir.file("a.rawlog") + "' --set vslam_sim.duration=30").exitCode, 0);
	ASSERT_EQ(runCommand(sim + "'" + dir.file("b.rawlog") + "' --set vslam_sim.duration=30").exitCode, 0);
	EXPECT_EQ(readFile(dir.file("a_groundtruth.tum")), readFile(dir.file("b_groundtruth.tum")));
	EXPECT_EQ(readFile(dir.file("a.rawlog")), readFile(dir.file("b.rawlog")));
	const auto typo = runCommand(sim + "'" + dir.file("c.rawlog") + "' --set vslam_sim.durration=30");
	EXPECT_NE(typo.exitCode, 0);
	EXPECT_TRUE(contains(typo.output, "did you mean 'duration'")) << typo.output;

	const auto e = runCommand(kBin + "vslam-eval '" + dir.file("a_groundtruth.tum") + "' '" +
		dir.file("a_groundtruth.tum") + "'");
	ASSERT_EQ(e.exitCode, 0) << e.output;
	EXPECT_TRUE(contains(e.output, "rmse 0.0000")) << e.output;
	const auto m = runCommand(kBin + "vslam-eval '" + dir.file("missing.tum") + "' '" +
		dir.file("a_groundtruth.tum") + "'");
	EXPECT_NE(m.exitCode, 0);
	EXPECT_TRUE(contains(m.output, "missing.tum")) << m.output;
}

/** vslam-simul as users run it: a generated rawlog that vslam (images
 * through the front-end) and MRPT's rbpf-slam (grid mapping with the
 * laser) both run without conversion, and bad scenario files that end in
 * one clear error. Uses the shipped worlds (textures from the packages the
 * set-up script installs). */
#include <gtest/gtest.h>
#include <tests/support/RunCommand.h>
#include <tests/support/TempDir.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using vslam::testing::readFile;
using vslam::testing::contains;
using vslam::testing::runCommand;
using vslam::testing::TempDir;
namespace fs = std::filesystem;

namespace
{
const std::string kSource = VSLAM_SOURCE_DIR;
const std::string kBin = std::string(VSLAM_BINARY_DIR) + "/bin/";


size_t dataRows(const std::string& file)
{
	std::ifstream in(file);
	size_t n = 0;
	for (std::string line; std::getline(in, line);)
		if (!line.empty() && line[0] != '%' && line[0] != '#') n++;
	return n;
}

double rmseOf(const std::string& evalOutput)
{
	const auto at = evalOutput.find("rmse ");
	return at == std::string::npos ? 1e9 : std::stod(evalOutput.substr(at + 5));
}
}  // namespace

TEST(VslamSimul, WritesARawlogThatVslamAndRbpfSlamBothRun)
{
	TempDir dir;
	const std::string rawlog = (dir.path() / "sim.rawlog").string();
	const auto sim = runCommand(kBin + "vslam-simul '" + kSource + "/config_ini/simul_demo.ini' '" + rawlog +
		"' --quiet --set vslam_simul.duration=40");
	ASSERT_EQ(sim.exitCode, 0) << sim.output;
	EXPECT_TRUE(contains(sim.output, "200 steps (40 s simulated), 200 images")) << sim.output;
	for (const char* f : {"sim_groundtruth.tum", "sim_odometry.tum", "sim_preview.png", "sim_Images/img_2.jpg"})
		EXPECT_TRUE(fs::exists(dir.path() / f)) << f;
	EXPECT_EQ(dataRows((dir.path() / "sim_groundtruth.tum").string()), 200u);

	// vslam: images -> front-end -> filter, in one run.
	const auto v = runCommand(kBin + "vslam '" + kSource + "/config_ini/demo_rendered.ini' '" + rawlog + "' --out '" +
		(dir.path() / "vslam_out").string() + "' --quiet --set vslam.ground_truth_file=" +
		(dir.path() / "sim_groundtruth.tum").string());
	ASSERT_EQ(v.exitCode, 0) << v.output;
	const std::string summary = readFile((dir.path() / "vslam_out/run_summary.yaml").string());
	EXPECT_TRUE(contains(summary, "images: 200")) << summary;
	EXPECT_EQ(dataRows((dir.path() / "vslam_out/estimated_path.tum").string()), 200u);

	// rbpf-slam: grid mapping with the laser of the same rawlog.
	if (!fs::exists("/usr/bin/rbpf-slam")) GTEST_SKIP() << "rbpf-slam not installed (package mrpt-apps)";
	const auto r = runCommand("cd '" + dir.path().string() + "' && ASAN_OPTIONS=detect_leaks=0 rbpf-slam '" +
		kSource + "/config_ini/peers/rbpf-slam_gridmapping.ini' '" + rawlog + "'");
	ASSERT_EQ(r.exitCode, 0) << r.output.substr(r.output.size() > 3000 ? r.output.size() - 3000 : 0);
	const std::string path = (dir.path() / "rbpf-slam_out/log_estimated_path.txt").string();
	EXPECT_EQ(dataRows(path), 200u);
	// Its path starts at its own origin: compare after SE(2) alignment.
	const auto e = runCommand(kBin + "vslam-eval '" + path + "' '" + (dir.path() / "sim_groundtruth.tum").string() +
		"' --align");
	ASSERT_EQ(e.exitCode, 0) << e.output;
	EXPECT_LT(rmseOf(e.output), 0.3) << e.output;
}

TEST(VslamSimul, BadScenarioFilesEndInOneClearError)
{
	TempDir dir;
	const auto file = [&](const std::string& name, const std::string& text) {
		std::ofstream(dir.path() / name) << text;
		return (dir.path() / name).string();
	};
	const std::string room =
		"wall 0 0 4 0 0.1 backgrounds/mate/nature/Dune.jpg\n"
		"wall 4 0 4 3 0.1 backgrounds/mate/nature/Dune.jpg\n"
		"wall 4 3 0 3 0.1 backgrounds/mate/nature/Dune.jpg\n"
		"wall 0 3 0 0 0.1 backgrounds/mate/nature/Dune.jpg\n"
		"box 2 1.5 0 0.6 0.6 0.8 backgrounds/mate/nature/Garden.jpg\n";
	file("room.world", room);
	file("typo.world", room + "picture 1 0.05 2 0.05 1 1.6 backgrounds/mate/nature/Gardn.jpg\n");
	file("empty.world", "# nothing here\nceiling_height 2.5\n");
	const auto run = [&](const std::string& world, const std::string& extra) {
		const std::string start = extra.find("start_pose") == std::string::npos ? "start_pose = 1 1 0\n" : "";
		const std::string ini = file("s.ini",
			"[vslam_simul]\nworld_file = " + world + "\nduration = 5\n" + start + extra);
		return runCommand(kBin + "vslam-simul '" + ini + "' '" + (dir.path() / "out.rawlog").string() + "' --quiet");
	};
	struct Case
	{
		std::string world, extra, message;
		int exitCode;
	};
	const Case cases[] = {
		{"typo.world", "", "world file '" + (dir.path() / "typo.world").string() + "' line 6: unknown texture "
			"'backgrounds/mate/nature/Gardn.jpg'", 3},
		{"empty.world", "", "empty world (no wall)", 3},
		{"missing.world", "", "cannot read world file", 3},
		{"room.world", "path_type = waypoints\nwaypoints = 1 1 3 2\n",
			"the leg from point 1 (1.00, 1.00) -> (3.00, 2.00) runs through", 3},
		{"room.world", "start_pose = 2 1.5 0\n", "the start position (2.000000, 1.500000) is not free", 3},
		{"room.world", "camera_fxx = 300\n", "unknown key 'camera_fxx' in section [vslam_simul] (did you mean 'camera_fx'?)", 2},
		{"room.world", "camera_rate = 2\n", "camera_rate: one frame every whole number of steps", 2},
		{"room.world", "people = 1 0.5 0.5 3.5 2.5\n", "people: expected groups of 't x0 y0 x1 y1 speed'", 2},
	};
	for (const auto& c : cases)
	{
		SCOPED_TRACE(c.world + " / " + c.extra);
		const auto r = run(c.world, c.extra);
		EXPECT_EQ(r.exitCode, c.exitCode) << r.output;
		EXPECT_TRUE(contains(r.output, c.message)) << r.output;
		EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << "one line: " << r.output;
		EXPECT_FALSE(fs::exists(dir.path() / "out.rawlog"));
	}
	// The good room runs.
	const auto ok = run("room.world", "");
	EXPECT_EQ(ok.exitCode, 0) << ok.output;
}

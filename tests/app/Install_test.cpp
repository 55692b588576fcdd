/** cmake --install as a user or a packager runs it: the apps run from the
 * prefix on the installed example data, and another CMake project finds
 * the package and links the observation types. */
#include <gtest/gtest.h>
#include <tests/support/RunCommand.h>
#include <tests/support/TempDir.h>

#include <filesystem>
#include <fstream>
#include <string>

using vslam::testing::contains;
using vslam::testing::quoted;
using vslam::testing::runCommand;
using vslam::testing::TempDir;
namespace fs = std::filesystem;

namespace
{
const std::string kBuild = VSLAM_BINARY_DIR;

/** Installs the build into a fresh prefix; the prefix's path. */
std::string installInto(const TempDir& dir)
{
	const std::string prefix = dir.file("prefix");
	const auto r = runCommand("cmake --install " + quoted(kBuild) + " --prefix " + quoted(prefix));
	EXPECT_EQ(r.exitCode, 0) << r.output;
	return prefix;
}
}  // namespace

TEST(Install, TheInstalledVslamRunsTheInstalledDemo)
{
	TempDir dir;
	const std::string prefix = installInto(dir);
	for (const char* app : {"vslam", "vslam-simul", "vslam-frontend", "vslam-eval", "vslam-batch", "mrclam2rawlog"})
		EXPECT_TRUE(fs::exists(prefix + "/bin/" + app)) << app;
	EXPECT_TRUE(fs::exists(prefix + "/share/vslam/config_ini/camera.ini"));
	// From an unrelated working folder, so nothing resolves against the build.
	const auto r = runCommand("cd " + quoted(dir.path().string()) + " && " + quoted(prefix + "/bin/vslam") + " " +
		quoted(prefix + "/share/vslam/config_ini/demo_visual.ini") + " --out out --quiet --set vslam.max_steps=300");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_TRUE(fs::exists(dir.file("out/estimated_path.tum")));
	EXPECT_TRUE(contains(r.output, "ATE")) << r.output;  // the installed ground truth was found
	// The apps find the observation library in the prefix, not in the build.
	const auto ldd = runCommand("ldd " + quoted(prefix + "/bin/vslam"));
	EXPECT_TRUE(contains(ldd.output, prefix + "/bin/../lib")) << ldd.output;
}

TEST(Install, AnotherProjectFindsThePackageAndReadsTheObservations)
{
	TempDir dir;
	const std::string prefix = installInto(dir);
	const std::string src = dir.file("consumer");
	fs::create_directories(src);
	std::ofstream(src + "/CMakeLists.txt") << "cmake_minimum_required(VERSION 3.16)\n"
											  "project(consumer LANGUAGES CXX)\n"
											  "set(CMAKE_CXX_STANDARD 17)\n"
											  "find_package(vslam 0.1 REQUIRED)\n"
											  "add_executable(consumer main.cpp)\n"
											  "target_link_libraries(consumer PRIVATE vslam::vslam_obs)\n";
	std::ofstream(src + "/main.cpp") << "#include <libvslam/obs/CObservationVisualLandmark.h>\n"
										"#include <iostream>\n"
										"int main() {\n"
										"  vslam::CObservationVisualLandmark o;\n"
										"  o.landmarkID = 7;\n"
										"  std::cout << o.GetRuntimeClass()->className << ' ' << o.landmarkID << '\\n';\n"
										"}\n";
	// A sanitized build's library needs its runtime in the consumer too.
	const std::string sanitize = std::string(VSLAM_SANITIZER_RUNTIME).empty()
		? ""
		: " -DCMAKE_CXX_FLAGS=-fsanitize=address,undefined";
	const auto configure = runCommand("cmake -S " + quoted(src) + " -B " + quoted(src + "/build") +
		" -DCMAKE_PREFIX_PATH=" + quoted(prefix) + sanitize);
	ASSERT_EQ(configure.exitCode, 0) << configure.output;
	const auto build = runCommand("cmake --build " + quoted(src + "/build"));
	ASSERT_EQ(build.exitCode, 0) << build.output;
	const auto run = runCommand(quoted(src + "/build/consumer"));
	ASSERT_EQ(run.exitCode, 0) << run.output;
	EXPECT_TRUE(contains(run.output, "CObservationVisualLandmark 7")) << run.output;
}

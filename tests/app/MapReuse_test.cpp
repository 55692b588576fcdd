/** Map once, localize later: the final_map.vslam of one run as the prior
 * map of a second run on another path through the same room (another
 * circle, another start, darker images), kept fixed (localization_only)
 * or extended; and map files that cannot be used. Images come from the
 * textured-room fixture (tests/support/RoomImageRawlog.h). */
#include <gtest/gtest.h>
#include <libvslam/app/RunSummary.h>
#include <libvslam/io/VSlamMapFile.h>
#include <tests/support/RoomImageRawlog.h>
#include <tests/support/RunCommand.h>
#include <tests/support/TempDir.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>

using vslam::testing::quoted;
using vslam::testing::readFile;
using vslam::testing::runCommand;
using vslam::testing::TempDir;
namespace fs = std::filesystem;

namespace
{
const std::string kBin = std::string(VSLAM_BINARY_DIR) + "/bin/";

/** An INI for vslam on `rawlog` (100 particles, seed 1, the start from the
 * ground truth unless the start pose is unknown: both runs' maps share the
 * room's frame), with `extra` keys in [vslam]. */
std::string writeIni(const TempDir& dir, const std::string& name, const std::string& rawlog, const std::string& extra)
{
	const std::string ini = dir.file(name + ".ini");
	const bool unknownStart = extra.find("initial_pose_unknown = true") != std::string::npos;
	std::ofstream(ini) << "[vslam]\nrawlog_file = " << rawlog << "\nRANDOM_SEED = 1\n"
					   << "ground_truth_file = " << vslam::siblingFile(rawlog, "_groundtruth.tum") << "\n"
					   << "initial_pose_from_ground_truth = " << (unknownStart ? "false" : "true") << "\n"
					   << extra << "[vslam_particle_filter]\nsampleSize = 100\n";
	return ini;
}

vslam::testing::CommandResult runVslam(const TempDir& dir, const std::string& name, const std::string& rawlog,
	const std::string& extra)
{
	return runCommand(quoted(kBin + "vslam") + " " + quoted(writeIni(dir, name, rawlog, extra)) + " --quiet --out " +
		quoted(dir.file(name)));
}

double summaryValue(const std::string& summaryFile, const std::string& path)
{
	return vslam::summaryNumber(vslam::readRunSummary(summaryFile), path);
}

std::set<int64_t> visualIds(const vslam::CVSlamMap& map)
{
	std::set<int64_t> ids;
	for (const auto& e : map.estimates)
		if (e.kind == 0) ids.insert(e.id);
	return ids;
}
}  // namespace

/** One mapping run (1.5 laps of a 1 m circle, a 5% turn bias in the
 * odometry) shared by the tests, and a second drive through the same room:
 * one lap of a 0.8 m circle starting at another place, images at 70%
 * brightness. */
class MapReuse : public ::testing::Test
{
   protected:
	static void SetUpTestSuite()
	{
		dir = std::make_unique<TempDir>();
		vslam::testing::TRoomRawlogOptions first;
		first.odometryTurnScale = 1.05;
		vslam::testing::writeRoomImageRawlog(dir->file("first.rawlog"), first);
		vslam::testing::TRoomRawlogOptions second = first;
		second.laps = 1;
		second.radius = 0.8;
		second.startAngle = 2.0;
		second.brightness = 0.7;
		secondImages = vslam::testing::writeRoomImageRawlog(dir->file("second.rawlog"), second);
		mapping = runVslam(*dir, "map", dir->file("first.rawlog"), "");
		mapFile = dir->file("map/final_map.vslam");
	}
	static void TearDownTestSuite() { dir.reset(); }

	/** Runs vslam as `name` on `rawlog` with the map as prior_map_file and
	 * `keys` in [vslam]; returns its summary file ("" if it failed). */
	static std::string runOnTheMap(const std::string& name, const std::string& rawlog, const std::string& keys)
	{
		const auto r = runVslam(*dir, name, dir->file(rawlog), "prior_map_file = " + mapFile + "\n" + keys);
		EXPECT_EQ(r.exitCode, 0) << r.output;
		return r.exitCode == 0 ? dir->file(name + "/run_summary.yaml") : "";
	}

	static std::unique_ptr<TempDir> dir;
	static vslam::testing::CommandResult mapping;
	static std::string mapFile;
	static int secondImages;
};
std::unique_ptr<TempDir> MapReuse::dir;
vslam::testing::CommandResult MapReuse::mapping;
std::string MapReuse::mapFile;
int MapReuse::secondImages = 0;

TEST_F(MapReuse, TheMapFileHoldsEveryLandmarkWithWhatTheCameraRecognizesItBy)
{
	ASSERT_EQ(mapping.exitCode, 0) << mapping.output;
	const auto map = vslam::readVSlamMap(mapFile);
	const double landmarks = summaryValue(dir->file("map/run_summary.yaml"), "landmarks.total");
	EXPECT_EQ(map.estimates.size(), landmarks);
	EXPECT_GE(map.appearances.size(), 3u);
	EXPECT_EQ(map.descriptorStorage, "uint8");
	EXPECT_TRUE(map.hasCamera);
	EXPECT_EQ(map.camera.ncols, 320u);
	for (const auto& a : map.appearances) EXPECT_TRUE(visualIds(map).count(a.id)) << a.id;
	EXPECT_FALSE(fs::exists(mapFile + ".tmp"));
}

TEST_F(MapReuse, ALocalizationRunOnAnotherPathUsesTheMapAndLeavesItAsItWas)
{
	ASSERT_EQ(mapping.exitCode, 0) << mapping.output;
	const std::string summary = runOnTheMap("localize", "second.rawlog", "localization_only = true\n");
	ASSERT_FALSE(summary.empty());
	EXPECT_EQ(summaryValue(summary, "front_end.landmarks_created"), 0);
	EXPECT_NE(readFile(summary).find("map_fixed: true"), std::string::npos);
	EXPECT_GT(summaryValue(summary, "front_end.measurements"), secondImages / 3) << readFile(summary);
	// The map comes out as it went in.
	const auto before = vslam::readVSlamMap(mapFile), after = vslam::readVSlamMap(dir->file("localize/final_map.vslam"));
	ASSERT_EQ(after.estimates.size(), before.estimates.size());
	for (size_t i = 0; i < before.estimates.size(); i++)
	{
		EXPECT_EQ(after.estimates[i].id, before.estimates[i].id);
		EXPECT_EQ(after.estimates[i].mean, before.estimates[i].mean);
	}
	EXPECT_EQ(after.appearances.size(), before.appearances.size());
	// In the map, the second drive is at least as good as the run that made
	// it, and better than dead reckoning (measured: 0.038 m against the
	// mapping run's 0.133 m and dead reckoning's 0.130 m).
	const double localized = summaryValue(summary, "error_vs_ground_truth_m.vslam.mean");
	EXPECT_LT(localized, summaryValue(summary, "error_vs_ground_truth_m.dead_reckoning.mean")) << readFile(summary);
	EXPECT_LE(localized, summaryValue(dir->file("map/run_summary.yaml"), "error_vs_ground_truth_m.vslam.mean"))
		<< readFile(summary);
}

TEST_F(MapReuse, AMapBuiltWithAnotherCalibrationStillLocalizes)
{
	// The landmarks' points are metric, so a 400x300 camera (another focal
	// length in pixels) recognizes what a 320x240 one mapped.
	ASSERT_EQ(mapping.exitCode, 0) << mapping.output;
	vslam::testing::TRoomRawlogOptions other;
	other.odometryTurnScale = 1.05;
	other.laps = 1;
	other.radius = 0.8;
	other.startAngle = 2.0;
	other.imageWidth = 400;
	const int images = vslam::testing::writeRoomImageRawlog(dir->file("wider.rawlog"), other);
	const std::string summary = runOnTheMap("wider", "wider.rawlog", "localization_only = true\n");
	ASSERT_FALSE(summary.empty());
	EXPECT_GT(summaryValue(summary, "front_end.measurements"), images / 3) << readFile(summary);
	EXPECT_LT(summaryValue(summary, "error_vs_ground_truth_m.vslam.mean"),
		summaryValue(summary, "error_vs_ground_truth_m.dead_reckoning.mean"));
}

TEST_F(MapReuse, AContinuedMapKeepsItsLandmarksAndGivesNewOnesNewIds)
{
	ASSERT_EQ(mapping.exitCode, 0) << mapping.output;
	const std::string summary = runOnTheMap("continue", "second.rawlog", "");
	ASSERT_FALSE(summary.empty());
	EXPECT_EQ(summaryValue(summary, "landmarks.events.duplicate_creations"), 0);
	EXPECT_NE(readFile(summary).find("map_fixed: false"), std::string::npos);
	const auto before = vslam::readVSlamMap(mapFile), after = vslam::readVSlamMap(dir->file("continue/final_map.vslam"));
	const auto old = visualIds(before), now = visualIds(after);
	EXPECT_TRUE(std::includes(now.begin(), now.end(), old.begin(), old.end()));
	const double created = summaryValue(summary, "front_end.landmarks_created");
	EXPECT_EQ(now.size(), old.size() + created);
	for (int64_t id : now)
		if (!old.count(id))
		{
			EXPECT_GE(id, before.nextVisualLandmarkId);
		}
	EXPECT_LT(summaryValue(summary, "error_vs_ground_truth_m.vslam.mean"),
		summaryValue(summary, "error_vs_ground_truth_m.dead_reckoning.mean"));
}

TEST_F(MapReuse, FromAnUnknownStartTheRobotFindsItselfInTheMap)
{
	ASSERT_EQ(mapping.exitCode, 0) << mapping.output;
	const std::string summary =
		runOnTheMap("unknown", "second.rawlog", "localization_only = true\ninitial_pose_unknown = true\n");
	ASSERT_FALSE(summary.empty());
	const double first = summaryValue(summary, "unknown_start_pose.first_mapped_landmark_measured_at_s");
	const double found = summaryValue(summary, "unknown_start_pose.found_at_s");
	const double unknownSteps = summaryValue(summary, "unknown_start_pose.steps_with_unknown_pose");
	std::printf("unknown start: first mapped landmark measured at %.1f s, found at %.1f s, ATE mean %.3f m\n", first,
		found, summaryValue(summary, "error_vs_ground_truth_m.vslam.mean"));
	EXPECT_LE(found - first, 10) << readFile(summary);
	EXPECT_GE(unknownSteps, 1);
	// Until found, the path files say so instead of giving a pose.
	const std::string tum = readFile(dir->file("unknown/estimated_path.tum"));
	size_t marks = 0;
	for (size_t at = tum.find("pose unknown"); at != std::string::npos; at = tum.find("pose unknown", at + 1)) marks++;
	EXPECT_EQ(marks, unknownSteps);
	// From where it was found on, the path is as good as with a known start.
	EXPECT_LT(summaryValue(summary, "error_vs_ground_truth_m.vslam.mean"), 0.1) << readFile(summary);
}

namespace
{
/** Runs vslam on the second rawlog with `extra` [vslam] keys; expects
 * `exitCode` and an error message containing every one of `parts`. */
void expectError(const TempDir& dir, const std::string& extra, int exitCode, std::initializer_list<std::string> parts)
{
	const auto r = runVslam(dir, "bad", dir.file("second.rawlog"), extra);
	EXPECT_EQ(r.exitCode, exitCode) << r.output;
	for (const auto& part : parts) EXPECT_NE(r.output.find(part), std::string::npos) << part << "\n" << r.output;
	EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << "one line:\n" << r.output;
}
}  // namespace

TEST_F(MapReuse, AMapFileThatCannotBeUsedGivesOneClearError)
{
	ASSERT_EQ(mapping.exitCode, 0) << mapping.output;
	const std::string bytes = readFile(mapFile);
	const std::string cut = dir->file("cut.vslam");
	std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
	expectError(*dir, "prior_map_file = " + cut + "\n", 3, {"[vslam] prior_map_file", "cut.vslam", "truncated"});
	// A rawlog is a serialized MRPT file too, but not a map.
	expectError(*dir, "prior_map_file = " + dir->file("second.rawlog") + "\n", 3, {"second.rawlog", "not a vslam map"});
	std::string newer = bytes;
	newer[1 + std::string("vslam::CVSlamMap").size()] = 1;  // the version byte
	const std::string newerFile = dir->file("newer.vslam");
	std::ofstream(newerFile, std::ios::binary) << newer;
	expectError(*dir, "prior_map_file = " + newerFile + "\n", 3, {"newer.vslam", "another vslam version"});
	expectError(*dir, "localization_only = true\n", 2, {"localization_only", "needs [vslam] prior_map_file"});
	expectError(*dir, "initial_pose_unknown = true\n", 2, {"initial_pose_unknown", "needs [vslam] prior_map_file"});
	// A text map has no appearances: camera images cannot be localized in it.
	expectError(*dir, "prior_map_file = " + dir->file("map/final_map.txt") + "\nlocalization_only = true\n", 2,
		{"final_map.txt", "no visual landmark's appearance"});
}

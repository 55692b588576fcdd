/** Faults a long run meets and what vslam does about them: a full disk, an
 * unwritable folder, another run's ground truth, a folder an earlier run
 * left, a rerun from config_used.ini, INI mistakes MRPT would pass silently,
 * and corrupt rawlogs whose summaries must still be YAML. Each runs the
 * built binary as a user would. */
#include <gtest/gtest.h>
#include <libvslam/app/RunSummary.h>
#include <libvslam/io/Trajectory.h>
#include <libvslam/io/RawlogWriting.h>
#include <libvslam/models/SE2.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <tests/support/RunCommand.h>
#include <tests/support/TempDir.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>

using namespace vslam;
using vslam::testing::contains;
using vslam::testing::readFile;
using vslam::testing::runCommand;
using vslam::testing::TempDir;
namespace fs = std::filesystem;

namespace
{
std::string q(const std::string& s) { return vslam::testing::quoted(s); }
const std::string kSource = VSLAM_SOURCE_DIR;
const std::string kVslam = std::string(VSLAM_BINARY_DIR) + "/bin/vslam";
const std::string kDemoIni = kSource + "/config_ini/demo_visual.ini";
const std::string kDemoRawlog = kSource + "/rawlogs/demo_visual.rawlog";
const std::string kDemoTruth = kSource + "/rawlogs/demo_visual_groundtruth.tum";
const std::string kKfDemoRawlog = "/usr/share/mrpt/datasets/kf-slam_demo.rawlog";

/** vslam with the demo INI and the given arguments. */
vslam::testing::CommandResult runDemo(const std::string& args)
{
	return runCommand(q(kVslam) + " " + q(kDemoIni) + " --quiet " + args);
}

std::string summaryText(const std::string& out, const std::string& key)
{
	const auto summary = readRunSummary(out + "/run_summary.yaml");
	return summary.has(key) ? summary[key].as<std::string>() : "";
}

/** A small tmpfs mounted for the test (root only), unmounted at the end. */
class SmallDisk
{
   public:
	SmallDisk(const TempDir& dir, size_t kib) : m_path(dir.file("disk"))
	{
		fs::create_directories(m_path);
		const std::string options = "size=" + std::to_string(kib) + "k";
		m_mounted = geteuid() == 0 && mount("tmpfs", m_path.c_str(), "tmpfs", 0, options.c_str()) == 0;
	}
	~SmallDisk()
	{
		if (m_mounted) umount(m_path.c_str());
	}
	bool mounted() const { return m_mounted; }
	const std::string& path() const { return m_path; }

   private:
	std::string m_path;
	bool m_mounted = false;
};
}  // namespace

// --------------------------------------------------------------------------
// Outputs
// --------------------------------------------------------------------------
TEST(Reliability, AFullDiskIsAnErrorNamingTheFileWithTheSummarySayingSo)
{
	TempDir dir;
	// 140 KiB fills up at the end of the run (the final map), 60 KiB in the
	// middle (the paths written step by step).
	for (const size_t kib : {140, 60})
	{
		SmallDisk disk(dir, kib);
		std::string out, prefix;
		if (disk.mounted())
			out = disk.path() + "/o";
		else
		{
			// No root: the same failure from a limit on the size of any file
			// (the summary itself stays under it).
			out = dir.file("o" + std::to_string(kib));
			prefix = "trap '' XFSZ; ulimit -f " + std::to_string(kib / 8) + "; ";
		}
		const auto r = runCommand(prefix + q(kVslam) + " " + q(kDemoIni) + " --quiet --out " + q(out) +
			" --set vslam.max_steps=1500");
		EXPECT_EQ(r.exitCode, 4) << kib << " KiB\n" << r.output;
		EXPECT_TRUE(contains(r.output, "cannot write output file '" + out + "/")) << r.output;
		EXPECT_TRUE(contains(r.output, disk.mounted() ? "No space left on device" : "File too large")) << r.output;
		EXPECT_EQ(summaryText(out, "status"), "failed") << kib << " KiB";
		EXPECT_TRUE(contains(summaryText(out, "error"), "cannot write output file")) << kib << " KiB";
		EXPECT_FALSE(fs::exists(out + "/final_map.txt.tmp"));
		// Whatever paths were written hold whole rows up to the failure.
		if (fs::exists(out + "/log_estimated_path.txt")) readRbpfSlamPath(out + "/log_estimated_path.txt");
	}
}

TEST(Reliability, AnOutputFolderThatCannotBeMadeIsAnOutputErrorNotBadInput)
{
	TempDir dir;
	std::ofstream(dir.file("a_file")) << "x";
	const auto r = runDemo("--out " + q(dir.file("a_file/out")));
	EXPECT_EQ(r.exitCode, 4) << r.output;
	EXPECT_TRUE(contains(r.output, "cannot create output folder '" + dir.file("a_file/out") + "'")) << r.output;
}

TEST(Reliability, ARunClearsWhatAnEarlierRunLeftInItsFolder)
{
	TempDir dir;
	const std::string out = dir.file("o");
	ASSERT_EQ(runDemo("--out " + q(out) + " --set vslam.max_steps=300").exitCode, 0);
	const std::string firstId = summaryText(out, "run_id");
	ASSERT_TRUE(fs::exists(out + "/final_map.txt"));
	std::ofstream(out + "/notes.txt") << "the user's own file\n";
	// A second run into the same folder dies on a cut rawlog: nothing of the
	// first run may be left to pass for the second's.
	const std::string bytes = readFile(kDemoRawlog);
	const std::string cut = dir.file("cut.rawlog");
	std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
	const auto r = runDemo(q(cut) + " --out " + q(out) + " --set vslam.RANDOM_SEED=7");
	ASSERT_EQ(r.exitCode, 3) << r.output;
	const std::string secondId = summaryText(out, "run_id");
	EXPECT_NE(secondId, firstId);
	EXPECT_EQ(summaryText(out, "status"), "failed");
	// Every file that names its run names the second one.
	for (const char* f : {"estimated_path.tum", "final_map.txt", "most_likely_path.tum", "log_filter_steps.txt",
			 "config_used.ini"})
	{
		EXPECT_TRUE(contains(readFile(out + "/" + f), secondId)) << f;
		EXPECT_FALSE(contains(readFile(out + "/" + f), firstId)) << f;
	}
	EXPECT_EQ(readFile(out + "/notes.txt"), "the user's own file\n");
}

TEST(Reliability, ConfigUsedRerunsTheRunByteForByte)
{
	TempDir dir;
	// Relative paths, the rawlog on the command line, a clock seed: all
	// resolved in config_used.ini.
	const auto first = runCommand("cd " + q(kSource) + " && " + q(kVslam) +
		" config_ini/demo_visual.ini rawlogs/demo_visual.rawlog --quiet --out " + q(dir.file("a")) +
		" --set vslam.max_steps=600 --set vslam.RANDOM_SEED=-1");
	ASSERT_EQ(first.exitCode, 0) << first.output;
	fs::create_directories(dir.file("elsewhere"));
	const auto again = runCommand("cd " + q(dir.file("elsewhere")) + " && cp ../a/config_used.ini . && " +
		q(kVslam) + " config_used.ini --quiet --out " + q(dir.file("b")));
	ASSERT_EQ(again.exitCode, 0) << again.output;
	for (const char* f : {"log_estimated_path.txt", "estimated_path.tum", "final_map.txt", "most_likely_path.txt",
			 "smoothed_path.tum", "log_odometry_path.txt"})
		EXPECT_EQ(readFile(dir.file("a/") + f), readFile(dir.file("b/") + f)) << f;
	EXPECT_EQ(summaryText(dir.file("a"), "run_id"), summaryText(dir.file("b"), "run_id"));
	const std::string used = readFile(dir.file("a/config_used.ini"));
	EXPECT_TRUE(contains(used, "rawlog_file = " + kDemoRawlog)) << used;
	EXPECT_TRUE(contains(used, "output_dir = " + dir.file("a"))) << used;
}

// --------------------------------------------------------------------------
// Ground truth
// --------------------------------------------------------------------------
TEST(Reliability, AGroundTruthOfAnotherTimeIsAnErrorNamingTheKey)
{
	if (!fs::exists(kKfDemoRawlog)) GTEST_SKIP() << "MRPT's kf-slam demo rawlog is absent (package mrpt-common)";
	TempDir dir;
	// The demo INI's truth and start from it, with MRPT's demo rawlog.
	const auto start = runDemo(q(kKfDemoRawlog) + " --out " + q(dir.file("a")));
	EXPECT_EQ(start.exitCode, 2) << start.output;
	EXPECT_TRUE(contains(start.output, "[vslam] ground_truth_file '")) << start.output;
	EXPECT_TRUE(contains(start.output, "not this rawlog's ground truth")) << start.output;
	EXPECT_FALSE(fs::exists(dir.file("a")));
	// Without the start from it: the run is done, its figures are not.
	const auto run = runDemo(q(kKfDemoRawlog) + " --out " + q(dir.file("b")) +
		" --set vslam.initial_pose_from_ground_truth=false");
	EXPECT_EQ(run.exitCode, 2) << run.output;
	EXPECT_TRUE(contains(run.output, "has no pose at any step's time")) << run.output;
	EXPECT_EQ(summaryText(dir.file("b"), "status"), "failed");
	const auto summary = readRunSummary(dir.file("b/run_summary.yaml"));
	EXPECT_TRUE(summary["error_vs_ground_truth_m"]["vslam"].isNullNode()) << "an error over 0 poses is null";
}

TEST(Reliability, AnotherRunsGroundTruthOnTheSameClockIsAWarning)
{
	TempDir dir;
	// The demo's path mirrored: same clock, same speeds, turns the other way.
	Trajectory other = readTrajectory(kDemoTruth);
	for (auto& p : other) p.pose = {p.pose.x, -p.pose.y, -p.pose.phi};
	writeTumTrajectory(dir.file("other.tum"), other);
	const auto r = runDemo("--out " + q(dir.file("o")) + " --set vslam.max_steps=600 --set vslam.ground_truth_file=" +
		q(dir.file("other.tum")) + " --set vslam.initial_pose_from_ground_truth=false");
	EXPECT_EQ(r.exitCode, 0) << r.output;
	EXPECT_TRUE(contains(r.output, "warning: the odometry disagrees with [vslam] ground_truth_file")) << r.output;
	const auto summary = readRunSummary(dir.file("o/run_summary.yaml"));
	EXPECT_TRUE(contains(summary["error_vs_ground_truth_m"]["warning"].as<std::string>(), "disagrees"));
	// The run's own truth raises nothing.
	const auto own = runDemo("--out " + q(dir.file("own")) + " --set vslam.max_steps=600");
	EXPECT_EQ(own.exitCode, 0) << own.output;
	EXPECT_FALSE(contains(own.output, "warning")) << own.output;
	EXPECT_EQ(summaryNumber(readRunSummary(dir.file("own/run_summary.yaml")), "error_vs_ground_truth_m.ground_truth_cover"), 1);
}

TEST(Reliability, AGroundTruthCoveringPartOfTheRunIsAWarningWithTheShare)
{
	TempDir dir;
	Trajectory truth = readTrajectory(kDemoTruth), half;
	for (const auto& p : truth)
		if (p.t < truth.front().t + 30) half.push_back(p);
	writeTumTrajectory(dir.file("half.tum"), half);
	const auto r = runDemo("--out " + q(dir.file("o")) + " --set vslam.max_steps=600 --set vslam.ground_truth_file=" +
		q(dir.file("half.tum")));
	EXPECT_EQ(r.exitCode, 0) << r.output;
	EXPECT_TRUE(contains(r.output, "covers only 50.")) << r.output;
	const auto summary = readRunSummary(dir.file("o/run_summary.yaml"));
	EXPECT_NEAR(summaryNumber(summary, "error_vs_ground_truth_m.ground_truth_cover"), 0.5, 0.01);
	EXPECT_LT(summaryNumber(summary, "error_vs_ground_truth_m.vslam.associated_poses"), 310);
}

TEST(Reliability, AMissingGroundTruthFileNamesItsKey)
{
	TempDir dir;
	const auto r = runDemo("--out " + q(dir.file("o")) + " --set vslam.ground_truth_file=" + dir.file("nope.tum"));
	EXPECT_EQ(r.exitCode, 3) << r.output;
	EXPECT_TRUE(contains(r.output, "[vslam] ground_truth_file: ")) << r.output;
	EXPECT_TRUE(contains(r.output, dir.file("nope.tum"))) << r.output;
}

// --------------------------------------------------------------------------
// Numbers and configuration
// --------------------------------------------------------------------------
TEST(Reliability, AbsurdNoiseSettingsAreConfigurationErrorsNamingTheKey)
{
	for (const std::string set : {"vslam_motion_model.sigma_T=1e200", "vslam_visual.std_dx=1e200",
			 "vslam_range_bearing.std_range=1e6", "vslam_particle_filter.initial_std_xy=nan"})
	{
		TempDir dir;
		const auto r = runDemo("--out " + q(dir.file("o")) + " --set " + set);
		EXPECT_EQ(r.exitCode, 2) << set << "\n" << r.output;
		const std::string key = set.substr(set.find('.') + 1, set.find('=') - set.find('.') - 1);
		EXPECT_TRUE(contains(r.output, "] " + key + " = '")) << r.output;
		EXPECT_FALSE(fs::exists(dir.file("o")));
	}
}

TEST(Reliability, IniMistakesMrptWouldPassSilentlyAreErrorsNamingTheLine)
{
	TempDir dir;
	const std::string demo = readFile(kDemoIni);
	const auto check = [&](const std::string& name, const std::string& text, const std::string& expected) {
		const std::string ini = dir.file(name);
		std::ofstream(ini, std::ios::binary) << text;
		const auto r = runCommand(q(kVslam) + " " + q(ini) + " " + q(kDemoRawlog) + " --quiet --out " +
			q(dir.file("o_" + name)));
		EXPECT_EQ(r.exitCode, 2) << name << "\n" << r.output;
		EXPECT_TRUE(contains(r.output, expected)) << name << "\n" << r.output;
		EXPECT_LT(r.output.size(), 2000u) << name << ": the file is not echoed";
	};
	check("above.ini", "sampleSize = 10\n" + demo, "line 1: key 'sampleSize' is outside any [section]");
	check("twice_section.ini", demo + "\n[vslam_particle_filter]\nsampleSize = 10\n",
		"section [vslam_particle_filter] is given twice");
	check("twice.ini", "[vslam_particle_filter]\nsampleSize = 10\nBETA = 0.5\nsampleSize = 20\n",
		"line 4: key 'sampleSize' of [vslam_particle_filter] is given twice (also line 2)");
	check("hex.ini", "[vslam_particle_filter]\nBETA = 0x1\n", "not a decimal number");
	std::string binary(4096, '\0');
	for (size_t i = 0; i < binary.size(); i++) binary[i] = static_cast<char>(i * 7919 % 256);
	check("binary.ini", binary, "not an INI text file: binary data at byte 0");
	fs::create_directories(dir.file("folder.ini"));
	const auto r = runCommand(q(kVslam) + " " + q(dir.file("folder.ini")) + " " + q(kDemoRawlog));
	EXPECT_EQ(r.exitCode, 2) << r.output;
	EXPECT_TRUE(contains(r.output, "is a folder, not an INI file")) << r.output;
}

// --------------------------------------------------------------------------
// Rawlogs
// --------------------------------------------------------------------------
TEST(Reliability, RawlogsThatAreNotFilesOrAreEmptyAreNamed)
{
	TempDir dir;
	std::ofstream(dir.file("empty.rawlog"));
	fs::create_directories(dir.file("folder.rawlog"));
	ASSERT_EQ(mkfifo(dir.file("pipe.rawlog").c_str(), 0600), 0);
	const std::pair<std::string, std::string> cases[] = {{dir.file("empty.rawlog"), "is empty (0 bytes)"},
		{dir.file("folder.rawlog"), "it is a folder, not a file"}, {"/dev/null", "not a regular file"},
		{dir.file("pipe.rawlog"), "not a regular file"}};
	for (const auto& [rawlog, expected] : cases)
	{
		const auto r = runDemo(q(rawlog) + " --out " + q(dir.file("o")));
		EXPECT_EQ(r.exitCode, 3) << rawlog << "\n" << r.output;
		EXPECT_TRUE(contains(r.output, "'" + rawlog + "'")) << r.output;
		EXPECT_TRUE(contains(r.output, expected)) << r.output;
		EXPECT_FALSE(fs::exists(dir.file("o"))) << "nothing is written for an unreadable rawlog";
	}
}

TEST(Reliability, ACutGzipRawlogNamesTheEntryAndKeepsEveryWholeEntryBeforeTheCut)
{
	TempDir dir;
	const std::string bytes = readFile(kDemoRawlog);
	const std::string cut = dir.file("cut.rawlog");
	std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() * 3 / 4);
	const auto r = runDemo(q(cut) + " --out " + q(dir.file("o")));
	EXPECT_EQ(r.exitCode, 3) << r.output;
	EXPECT_TRUE(contains(r.output, "rawlog '" + cut + "', entry ")) << r.output;
	EXPECT_TRUE(contains(r.output, "is truncated")) << r.output;
	// The steps processed are those of every entry whole in what can be
	// decoded: the same as from the decoded bytes written plain (zlib's last
	// decoded block is read, not dropped).
	const std::string plain = dir.file("cut_plain.rawlog");
	runCommand("zcat " + q(cut) + " > " + q(plain) + " 2>/dev/null");
	const auto p = runDemo(q(plain) + " --out " + q(dir.file("p")));
	EXPECT_EQ(p.exitCode, 3) << p.output;
	const size_t steps = readRbpfSlamPath(dir.file("o/log_estimated_path.txt")).size();
	EXPECT_GT(steps, 1000u);
	EXPECT_EQ(steps, readRbpfSlamPath(dir.file("p/log_estimated_path.txt")).size());
}

TEST(Reliability, EverySummaryOfACorruptRawlogCorpusIsYaml)
{
	TempDir dir;
	const std::string bytes = readFile(kDemoRawlog);
	std::mt19937 rng(5);
	size_t failed = 0;
	for (int i = 0; i < 24; i++)
	{
		// Bit flips and cuts of the gzip file, and of its content written plain.
		std::string corrupt = bytes;
		const size_t at = 40 + rng() % (corrupt.size() - 80);
		if (i % 3 == 0)
			corrupt.resize(at);
		else
			for (int k = 0; k < 1 + i % 4; k++) corrupt[at + k] ^= static_cast<char>(1 + rng() % 255);
		const std::string file = dir.file("c" + std::to_string(i) + ".rawlog");
		std::ofstream(file, std::ios::binary) << corrupt;
		const std::string out = dir.file("o" + std::to_string(i));
		const auto r = runDemo(q(file) + " --out " + q(out));
		EXPECT_TRUE(r.exitCode == 0 || r.exitCode == 3) << file << "\n" << r.output;
		if (r.exitCode == 3 && fs::exists(out)) failed++;
		if (!fs::exists(out + "/run_summary.yaml")) continue;
		const auto summary = readRunSummary(out + "/run_summary.yaml");  // throws if not YAML
		EXPECT_EQ(summary["status"].as<std::string>(), r.exitCode == 0 ? "completed" : "failed");
		if (r.exitCode == 3)
		{
			EXPECT_FALSE(summary["error"].as<std::string>().empty());
		}
	}
	EXPECT_GE(failed, 12u) << "too few corruptions were caught: the corpus checks too little";
}

namespace
{
/** A robot circling three beacons (IDs 6-8) for 40 s, then switched off
 * for an hour and circling on for 40 s; beacon 99 is seen once, and two
 * sightings have impossible ranges: 0 and 50 m (beyond max_range 20). */
void writeGappedRangeBearingRawlog(const std::string& file)
{
	std::vector<ActionFramePair> steps;
	const double beacons[3][2] = {{3, 0}, {0, 3}, {-3, 0}};
	se2::Pose truth{0, -1, 0};
	const se2::Pose increment{0.2 * 0.2, 0, 0.2 * 0.2};  // 0.2 m/s on a 1 m radius
	for (int k = 0; k < 400; k++)
	{
		const double t = 1e9 + 0.2 * k + (k >= 200 ? 3600 : 0);
		const auto stamp = mrpt::Clock::fromDouble(t);
		if (k > 0) truth = se2::compose(truth, increment);
		mrpt::obs::CActionRobotMovement2D move;
		mrpt::obs::CActionRobotMovement2D::TMotionModelOptions model;
		model.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
		move.computeFromOdometry(mrpt::poses::CPose2D(k > 0 ? increment.x : 0, 0, k > 0 ? increment.phi : 0), model);
		move.timestamp = stamp;
		auto actions = mrpt::obs::CActionCollection::Create();
		actions->insert(move);
		auto obs = mrpt::obs::CObservationBearingRange::Create();
		obs->timestamp = stamp;
		obs->sensor_std_range = 0.05f;
		obs->sensor_std_yaw = 0.01f;
		const auto sight = [&](int id, double x, double y, double range) {
			mrpt::obs::CObservationBearingRange::TMeasurement m;
			m.landmarkID = id;
			m.range = static_cast<float>(range);
			m.yaw = static_cast<float>(se2::wrap(std::atan2(y - truth.y, x - truth.x) - truth.phi));
			m.pitch = 0;
			obs->sensedData.push_back(m);
		};
		for (int b = 0; b < 3; b++)
		{
			const double range = std::hypot(beacons[b][0] - truth.x, beacons[b][1] - truth.y);
			sight(6 + b, beacons[b][0], beacons[b][1], k == 60 && b == 0 ? 0.0 : k == 70 && b == 1 ? 50.0 : range);
		}
		if (k == 50) sight(99, 5, 5, std::hypot(5 - truth.x, 5 - truth.y));
		auto frame = mrpt::obs::CSensoryFrame::Create();
		frame->insert(obs);
		steps.emplace_back(actions, frame);
	}
	writeActionFrameRawlog(file, steps);
}
}  // namespace

TEST(Reliability, AnHourLongGapAnIdSeenOnceAndImpossibleRangesAreCountedNotFatal)
{
	TempDir dir;
	const std::string rawlog = dir.file("gap.rawlog");
	writeGappedRangeBearingRawlog(rawlog);
	const auto r = runCommand(q(kVslam) + " " + q(kSource + "/config_ini/mrclam_range_bearing.ini") + " " + q(rawlog) +
		" --out " + q(dir.file("o")) + " --quiet --set vslam_range_bearing.max_range=20");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const auto summary = readRunSummary(dir.file("o/run_summary.yaml"));
	EXPECT_EQ(summary["status"].as<std::string>(), "completed");
	EXPECT_NEAR(summaryNumber(summary, "rawlog.longest_gap_seconds"), 3600.2, 1e-3);
	EXPECT_EQ(summaryNumber(summary, "measurements.rejected.range_limits"), 2);
	EXPECT_EQ(summaryNumber(summary, "landmarks.total"), 4);
	EXPECT_EQ(summaryNumber(summary, "landmarks.never_seen_again"), 1);
	// Every pose finite, online and smoothed, across the gap.
	const Trajectory path = readTrajectory(dir.file("o/estimated_path.tum"));
	ASSERT_EQ(path.size(), 400u);
	for (const auto& p : path) ASSERT_TRUE(std::isfinite(p.pose.x) && std::isfinite(p.pose.y) && std::isfinite(p.pose.phi));
	const Trajectory smoothed = readTrajectory(dir.file("o/pose_graph_path.tum"));
	ASSERT_EQ(smoothed.size(), 400u);
	for (const auto& p : smoothed) ASSERT_TRUE(std::isfinite(p.pose.x) && std::isfinite(p.pose.phi));
}

TEST(Reliability, OutOfMemoryEndsWithExitFourAndTheSummarySayingSo)
{
	if (!std::string(VSLAM_SANITIZER_RUNTIME).empty())
		GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: no memory limit fits it";
	if (!fs::exists(kKfDemoRawlog)) GTEST_SKIP() << "MRPT's kf-slam demo rawlog is absent (package mrpt-common)";
	TempDir dir;
	// 100,000 particles with MRPT's range-bearing demo's 70 landmarks need
	// over 1 GB; the process gets 600 MB of address space.
	const auto r = runCommand("ulimit -v 600000; " + q(kVslam) + " " + q(kSource + "/config_ini/kfslam_demo_range_bearing.ini") +
		" --quiet --out " + q(dir.file("o")) + " --set vslam_particle_filter.sampleSize=100000 --set vslam.max_steps=20");
	EXPECT_EQ(r.exitCode, 4) << r.output;
	EXPECT_TRUE(contains(r.output, "out of memory")) << r.output;
	EXPECT_EQ(summaryText(dir.file("o"), "status"), "failed");
	EXPECT_EQ(summaryText(dir.file("o"), "error"), "out of memory");
}

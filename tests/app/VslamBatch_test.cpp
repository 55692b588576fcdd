/** vslam-batch as users run it: a grid over seeds in parallel, the summary,
 * resuming, one task at a time (the cluster path), and failures reported
 * without stopping the rest. */
#include <gtest/gtest.h>
#include <tests/support/RunCommand.h>
#include <tests/support/TempDir.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using vslam::testing::contains;
using vslam::testing::quoted;
using vslam::testing::readFile;
using vslam::testing::runCommand;
using vslam::testing::TempDir;
namespace fs = std::filesystem;

namespace
{
const std::string kSource = VSLAM_SOURCE_DIR;
const std::string kBatch = std::string(VSLAM_BINARY_DIR) + "/bin/vslam-batch ";

/** Two seeds x two particle counts on the demo's measurement rawlog (300
 * steps), plus, if asked, a scenario whose rawlog is corrupt. */
std::string writeBatch(const TempDir& dir, bool withBadScenario)
{
	const std::string file = dir.file("batch.ini");
	std::ofstream f(file);
	f << "[batch]\noutput_dir = out\nseeds = 1 2\njobs = 2\nvslam_ini = " << kSource
	  << "/config_ini/demo_visual.ini\nset = vslam.max_steps=300\n"
	  << "[scenario:demo]\nrawlog = " << kSource << "/rawlogs/demo_visual.rawlog\nground_truth = " << kSource
	  << "/rawlogs/demo_visual_groundtruth.tum\n"
	  << "[grid]\nvslam_particle_filter.sampleSize = 30 60\n";
	if (withBadScenario)
	{
		std::ofstream(dir.file("bad.rawlog")) << "not a rawlog\n";
		f << "[scenario:bad]\nrawlog = bad.rawlog\nground_truth = " << kSource
		  << "/rawlogs/demo_visual_groundtruth.tum\n";
	}
	return file;
}

/** The folder of the variation with this setting (folders are named by a
 * hash of the settings): the one whose first run's command line has it. */
std::string variationDir(const TempDir& dir, const std::string& scenario, const std::string& setting)
{
	for (const auto& entry : fs::directory_iterator(dir.file("out/" + scenario)))
	{
		const std::string command = readFile((entry.path() / "seed1" / "log.txt").string());
		if (contains(command, "--set " + setting + "\n") || contains(command, "--set " + setting + " "))
			return entry.path().string();
	}
	return "(no variation with " + setting + ")";
}

/** Runs every command of a --list-tasks output, each a complete shell
 * command, as a job array would; the number that failed. */
size_t runListedTasks(const std::string& list)
{
	std::istringstream lines(list);
	size_t failed = 0;
	for (std::string line; std::getline(lines, line);)
		if (contains(line, "--task"))
		{
			const auto r = runCommand(line);
			EXPECT_EQ(r.exitCode, 0) << line << "\n" << r.output;
			failed += r.exitCode != 0;
		}
	return failed;
}

size_t countLines(const std::string& text, const std::string& part)
{
	std::istringstream in(text);
	size_t n = 0;
	for (std::string l; std::getline(in, l);) n += contains(l, part);
	return n;
}
}  // namespace

TEST(VslamBatch, RunsTheGridSummarizesAndResumes)
{
	TempDir dir;
	const std::string batch = writeBatch(dir, false);
	const auto first = runCommand(kBatch + "'" + batch + "'");
	ASSERT_EQ(first.exitCode, 0) << first.output;
	EXPECT_TRUE(contains(first.output, "4 run, 0 done before, 0 failed")) << first.output;
	const std::string summary = readFile(dir.file("out/summary.md"));
	// Two tables (the metrics over seeds, then vslam beside dead reckoning and
	// the peers), one row per variation in each.
	EXPECT_EQ(countLines(summary, "| demo | vslam_particle_filter.sampleSize="), 4u) << summary;
	EXPECT_EQ(countLines(summary, "| 2 / 2 |"), 2u) << summary;
	EXPECT_TRUE(fs::exists(dir.file("out/summary_ate.png")));
	// One CSV row per run, with its seed and metrics.
	EXPECT_EQ(countLines(readFile(dir.file("out/summary.csv")), "demo,v"), 4u);
	const std::string v30 = variationDir(dir, "demo", "vslam_particle_filter.sampleSize=30");
	const std::string v60 = variationDir(dir, "demo", "vslam_particle_filter.sampleSize=60");
	const std::string metrics = readFile(v60 + "/seed2/metrics.txt");
	EXPECT_TRUE(contains(metrics, "ate_rmse ")) << metrics;
	EXPECT_TRUE(contains(metrics, "smoothed_ate_aligned_rmse ")) << metrics;
	EXPECT_TRUE(contains(metrics, "kidnaps_reverted ")) << metrics;
	EXPECT_TRUE(contains(readFile(v60 + "/seed2/vslam/config_used.ini"), "sampleSize = 60"));
	for (const char* figure : {"paths", "error_over_time", "measurements_per_landmark", "particle_spread", "dual_ratio"})
		EXPECT_TRUE(fs::exists(v60 + "/seed2/vslam/figures/" + figure + ".png")) << figure;

	// Resume: an unfinished run (no done file) runs again, the rest not.
	const std::string path = readFile(v30 + "/seed1/vslam/estimated_path.tum");
	fs::remove(v30 + "/seed1/done");
	const auto again = runCommand(kBatch + "'" + batch + "'");
	ASSERT_EQ(again.exitCode, 0) << again.output;
	EXPECT_TRUE(contains(again.output, "1 run, 3 done before, 0 failed")) << again.output;
	EXPECT_EQ(readFile(v30 + "/seed1/vslam/estimated_path.tum"), path);  // same seed, same run

	// Finished tasks stay finished when the binaries move: a record naming
	// the program in another folder is the same task.
	const std::string doneFile = v30 + "/seed2/done";
	const std::string record = readFile(doneFile);
	ASSERT_EQ(record.rfind("vslam ", 0), 0u) << record;  // recorded without the folder
	std::ofstream(doneFile) << "/another/build/bin/" << record;
	const auto moved = runCommand(kBatch + "'" + batch + "'");
	ASSERT_EQ(moved.exitCode, 0) << moved.output;
	EXPECT_TRUE(contains(moved.output, "0 run, 4 done before, 0 failed")) << moved.output;

	// Metrics of an older scoring are scored again from the outputs, without
	// running vslam again.
	const std::string metricsFile = v60 + "/seed1/metrics.txt";
	std::string old = readFile(metricsFile);
	const size_t at = old.find("scoring_version ");
	old.replace(at, old.find('\n', at) - at, "scoring_version 1");
	std::ofstream(metricsFile) << old;
	const auto rescored = runCommand(kBatch + "'" + batch + "'");
	ASSERT_EQ(rescored.exitCode, 0) << rescored.output;
	EXPECT_TRUE(contains(rescored.output, "run/demo/" + fs::path(v60).filename().string() + "/seed1: done before, scored again"))
		<< rescored.output;
	EXPECT_TRUE(contains(rescored.output, "0 run, 4 done before, 0 failed")) << rescored.output;
	EXPECT_FALSE(contains(readFile(metricsFile), "scoring_version 1\n"));
}

TEST(VslamBatch, ListedTasksRunOneByOneAsOnACluster)
{
	TempDir dir;
	const std::string batch = writeBatch(dir, false);
	const auto list = runCommand(kBatch + "'" + batch + "' --list-tasks");
	ASSERT_EQ(list.exitCode, 0) << list.output;
	EXPECT_EQ(countLines(list.output, " --task 'run/demo/"), 4u) << list.output;
	EXPECT_EQ(runListedTasks(list.output), 0u);
	const auto summary = runCommand(kBatch + "'" + batch + "' --summary");
	ASSERT_EQ(summary.exitCode, 0) << summary.output;
	EXPECT_EQ(countLines(readFile(dir.file("out/summary.md")), "| 2 / 2 |"), 2u);
	const auto unknown = runCommand(kBatch + "'" + batch + "' --task run/demo/v09/seed1");
	EXPECT_EQ(unknown.exitCode, 1);
	EXPECT_TRUE(contains(unknown.output, "no task 'run/demo/v09/seed1'")) << unknown.output;
}

TEST(VslamBatch, OverridesOnTheCommandLineReachEveryListedTask)
{
	TempDir dir;
	const std::string batch = writeBatch(dir, false);
	// The file's grid axis replaced by another, the outputs moved: a quoted
	// value with spaces and a quote must survive the listed shell commands.
	const std::string sets = " --set 'grid.vslam_particle_filter.sampleSize=' --set 'grid.vslam_mixture_proposal.dual_ratio=0.1 0.2'"
							 " --set " + quoted("batch.output_dir=" + dir.file("other's"));
	const auto list = runCommand(kBatch + "'" + batch + "' --list-tasks" + sets);
	ASSERT_EQ(list.exitCode, 0) << list.output;
	EXPECT_EQ(countLines(list.output, " --task 'run/demo/"), 4u) << list.output;
	EXPECT_EQ(runListedTasks(list.output), 0u);
	EXPECT_FALSE(fs::exists(dir.file("out")));
	const auto summary = runCommand(kBatch + "'" + batch + "' --summary" + sets);
	ASSERT_EQ(summary.exitCode, 0) << summary.output;
	const std::string table = readFile(dir.file("other's/summary.md"));
	EXPECT_EQ(countLines(table, "| demo | vslam_mixture_proposal.dual_ratio=0.1 | 2 / 2 |"), 1u) << table;
	EXPECT_EQ(countLines(table, "| demo | vslam_mixture_proposal.dual_ratio=0.2 | 2 / 2 |"), 1u) << table;
	EXPECT_EQ(countLines(table, "sampleSize"), 0u) << table;
	// A misspelt key is an error naming it, before anything runs; --set
	// without its value is a usage error.
	const auto misspelt = runCommand(kBatch + "'" + batch + "' --set batch.seed=3");
	EXPECT_EQ(misspelt.exitCode, 2) << misspelt.output;
	EXPECT_TRUE(contains(misspelt.output, "[batch] seed: unknown key (did you mean 'seeds'?)")) << misspelt.output;
	const auto noValue = runCommand(kBatch + "'" + batch + "' --set");
	EXPECT_EQ(noValue.exitCode, 1) << noValue.output;
}

TEST(VslamBatch, AFailedRunIsReportedAndTheOthersGoOn)
{
	TempDir dir;
	const auto r = runCommand(kBatch + "'" + writeBatch(dir, true) + "'");
	EXPECT_EQ(r.exitCode, 3) << r.output;
	EXPECT_EQ(countLines(r.output, "run/bad/"), 4u) << r.output;
	EXPECT_EQ(countLines(r.output, "FAILED: exit 3, see "), 4u) << r.output;
	EXPECT_TRUE(contains(r.output, "4 run, 0 done before, 4 failed")) << r.output;
	EXPECT_TRUE(contains(readFile(dir.file("out/summary.md")), "| bad | vslam_particle_filter.sampleSize=30 | 0 / 2 |"));
	const auto config = runCommand(kBatch + "'" + dir.file("nothing.ini") + "'");
	EXPECT_EQ(config.exitCode, 2);
	EXPECT_TRUE(contains(config.output, "no batch file")) << config.output;
}

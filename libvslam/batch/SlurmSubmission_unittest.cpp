/** vslam-batch --slurm's submission: the [slurm] keys, array chunks below
 * MaxArraySize, each scenario's runs waiting for its own renderings, and
 * resources from the finished tasks. (Submitting to a real cluster:
 * tests/slurm.) */
#include <gtest/gtest.h>
#include <libvslam/batch/BatchPlan.h>
#include <libvslam/batch/SlurmSubmission.h>
#include <libvslam/config/ConfigError.h>
#include <tests/support/RunCommand.h>
#include <tests/support/TempDir.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace vslam::batch;
using vslam::testing::contains;
using vslam::testing::readFile;
using vslam::testing::runCommand;
using vslam::testing::TempDir;

namespace
{
const std::string kSource = VSLAM_SOURCE_DIR;

/** Two seeds of a rendered scenario and of a fixed rawlog, two variations:
 * 2 renderings and 8 runs; then \a slurm as the [slurm] section. */
std::string writeBatch(const TempDir& dir, const std::string& slurm)
{
	const std::string file = dir.file("batch.ini");
	std::ofstream(file) << "[batch]\noutput_dir = out\nseeds = 1 2\nvslam_ini = " << kSource
						<< "/config_ini/demo_visual.ini\n[scenario:fixed]\nrawlog = " << kSource
						<< "/rawlogs/demo_visual.rawlog\nground_truth = " << kSource
						<< "/rawlogs/demo_visual_groundtruth.tum\n[scenario:home]\nsimul_ini = " << kSource
						<< "/config_ini/simul_demo.ini\nvslam_ini = " << kSource << "/config_ini/demo_rendered.ini\n"
						<< "[grid]\nvslam_particle_filter.sampleSize = 30 60\n"
						<< slurm;
	return file;
}

std::string errorOf(const std::string& file, const std::vector<std::string>& overrides = {})
{
	try
	{
		loadBatchPlan(file, overrides);
	}
	catch (const vslam::ConfigError& e)
	{
		return e.what();
	}
	return "";
}

size_t countOf(const std::string& text, const std::string& part)
{
	size_t n = 0;
	for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) n++;
	return n;
}
}  // namespace

TEST(SlurmSubmission, ArrayChunksKeepEveryIndexBelowMaxArraySize)
{
	using Chunks = std::vector<std::pair<size_t, size_t>>;
	EXPECT_EQ(arrayChunks(1, 2500, 1001), (Chunks{{1, 1001}, {1002, 1001}, {2003, 498}}));
	EXPECT_EQ(arrayChunks(7, 3, 1001), (Chunks{{7, 3}}));
	EXPECT_EQ(arrayChunks(1, 0, 1001), Chunks{});
	EXPECT_EQ(arrayChunks(1, 2, 1), (Chunks{{1, 1}, {2, 1}}));
}

TEST(SlurmSubmission, SlurmKeysAreCheckedAndCanBeSetFromTheCommandLine)
{
	TempDir dir;
	EXPECT_TRUE(contains(errorOf(writeBatch(dir, "[slurm]\nthrotle = 2\n")), "[slurm] throtle: unknown key (did you mean 'throttle'?)"));
	EXPECT_TRUE(contains(errorOf(writeBatch(dir, "[slurm]\ncpus_per_task = 0\n")), "[slurm] cpus_per_task = '0': out of range"));
	EXPECT_TRUE(contains(errorOf(writeBatch(dir, "[slurm]\nmem_mib = 2G\n")), "[slurm] mem_mib = '2G': not an integer"));
	const auto plan = loadBatchPlan(writeBatch(dir, ""), {"slurm.throttle=3", "slurm.sbatch_options=--qos=low --nice=5"});
	EXPECT_EQ(plan.slurm.throttle, 3);
	EXPECT_EQ(plan.slurm.sbatchOptions, (std::vector<std::string>{"--qos=low", "--nice=5"}));
	EXPECT_EQ(plan.slurm.cpusPerTask, 1);
}

TEST(SlurmSubmission, EachScenariosRunsWaitForItsOwnRenderingsInChunks)
{
	TempDir dir;
	const auto plan = loadBatchPlan(writeBatch(dir,
		"[slurm]\nmax_array_size = 3\nthrottle = 2\ncpus_per_task = 2\nmem_mib = 900\ntime_minutes = 15\n"
		"partition = short\nsbatch_options = --qos=low\n"));
	const SlurmSubmission sub = writeSlurmSubmission(plan, "/opt/vslam/bin", dir.file("sub"));
	EXPECT_EQ(sub.renderings, 2u);
	EXPECT_EQ(sub.runs, 8u);
	EXPECT_EQ(sub.arrays, 5u);  // fixed: 3 + 1 runs; home: 2 renderings, 3 + 1 runs
	EXPECT_EQ(sub.runNeeds.basis, "configured");

	// tasks.txt: each scenario's renderings, then its runs (scenarios in name order).
	std::istringstream tasks(readFile(dir.file("sub/tasks.txt")));
	std::vector<std::string> lines;
	for (std::string l; std::getline(tasks, l);) lines.push_back(l);
	ASSERT_EQ(lines.size(), 10u);
	EXPECT_TRUE(contains(lines[0], "--task 'run/fixed/"));
	EXPECT_TRUE(contains(lines[4], "--task 'render/home/seed1'"));
	EXPECT_TRUE(contains(lines[6], "--task 'run/home/"));
	EXPECT_EQ(lines[0].rfind("'/opt/vslam/bin/vslam-batch' '" + dir.file("batch.ini") + "'", 0), 0u);

	const std::string submit = readFile(dir.file("sub/submit.sh"));
	EXPECT_EQ(countOf(submit, "--array=0-2%2"), 2u);  // both scenarios' first run chunk
	EXPECT_EQ(countOf(submit, "--array=0-1%2 "), 1u);  // the renderings
	EXPECT_EQ(countOf(submit, "task.sh 1)"), 1u);
	EXPECT_EQ(countOf(submit, "task.sh 4)"), 1u);
	EXPECT_EQ(countOf(submit, "task.sh 5)"), 1u);
	EXPECT_EQ(countOf(submit, "task.sh 7)"), 1u);
	EXPECT_EQ(countOf(submit, "task.sh 10)"), 1u);
	// Only the rendered home's two run arrays depend on renderings.
	EXPECT_EQ(countOf(submit, "--dependency=afterok$renders --kill-on-invalid-dep=yes"), 2u);
	EXPECT_EQ(countOf(submit, "--dependency=afterany$runs"), 1u);
	EXPECT_EQ(countOf(submit, "--cpus-per-task=2 --mem=900M --time=15"), 5u);
	EXPECT_EQ(countOf(submit, "--partition='short' '--qos=low'"), 6u);
	for (const char* script : {"submit.sh", "task.sh", "summary.sh"})
		EXPECT_EQ(runCommand("bash -n " + dir.file(std::string("sub/") + script)).exitCode, 0) << script;
	EXPECT_TRUE(contains(readFile(dir.file("sub/summary.sh")), "--summary"));
}

TEST(SlurmSubmission, ResourcesComeFromTheFinishedTasksWithAMargin)
{
	TempDir dir;
	const auto plan = loadBatchPlan(writeBatch(dir, ""));
	const SlurmNeeds none = slurmNeeds(plan, {Task::Kind::Run});
	EXPECT_EQ(none.memMiB, 4096);
	EXPECT_EQ(none.timeMinutes, 120);
	EXPECT_EQ(none.basis, "default: nothing measured yet");
	int written = 0;
	for (const auto& task : plan.tasks)
		if (task.kind == Task::Kind::Run && written < 2)
		{
			std::filesystem::create_directories(task.dir);
			std::ofstream(task.dir + "/metrics.txt") << "peak_mib " << (written ? 300 : 500) << "\nwall_s "
													 << (written ? 600 : 30) << "\n";
			written++;
		}
	const SlurmNeeds measured = slurmNeeds(plan, {Task::Kind::Run});
	EXPECT_EQ(measured.memMiB, 1024);  // 1.5 x 500 + 256 = 1006, to 64 MiB
	EXPECT_EQ(measured.timeMinutes, 25);  // 2 x 600 s + 5 min
	EXPECT_EQ(measured.basis, "measured on 2 finished tasks");
	EXPECT_EQ(slurmNeeds(plan, {Task::Kind::Render}).memMiB, 4096);  // the renderings: nothing measured

	auto configured = plan;
	configured.slurm.memMiB = 700;
	EXPECT_EQ(slurmNeeds(configured, {Task::Kind::Run}).memMiB, 700);
	EXPECT_EQ(slurmNeeds(configured, {Task::Kind::Run}).timeMinutes, 25);  // still measured
}

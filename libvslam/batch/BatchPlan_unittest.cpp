#include <gtest/gtest.h>
#include <libvslam/batch/BatchPlan.h>
#include <libvslam/config/ConfigError.h>
#include <tests/support/TempDir.h>

#include <filesystem>
#include <fstream>

using namespace vslam::batch;
using vslam::testing::TempDir;

namespace
{
const std::string kSource = VSLAM_SOURCE_DIR;

/** A batch file in \a dir with fixed data from the repository. */
std::string writeBatch(const TempDir& dir, const std::string& batchSection, const std::string& rest)
{
	const std::string file = dir.file("batch.ini");
	std::ofstream(file) << "[batch]\noutput_dir = out\nvslam_ini = " << kSource << "/config_ini/demo_visual.ini\n"
						<< batchSection << "\n[scenario:demo]\nrawlog = " << kSource
						<< "/rawlogs/demo_visual.rawlog\nground_truth = " << kSource
						<< "/rawlogs/demo_visual_groundtruth.tum\n"
						<< rest;
	return file;
}

std::string errorOf(const std::string& file)
{
	try
	{
		loadBatchPlan(file);
	}
	catch (const vslam::ConfigError& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(BatchPlan, TheGridTimesTheSeedsGivesTheRunsInOrder)
{
	TempDir dir;
	const auto plan = loadBatchPlan(writeBatch(dir, "seeds = 1-3 7",
		"[grid]\nvslam_particle_filter.sampleSize = 50 100\nvslam_mixture_proposal.dual_ratio = 0 0.1 0.2\n"));
	EXPECT_EQ(plan.seeds, (std::vector<int>{1, 2, 3, 7}));
	ASSERT_EQ(plan.variations.size(), 6u);
	// Keys in alphabetical order, the first varying slowest.
	EXPECT_EQ(plan.variations[0].label(), "vslam_mixture_proposal.dual_ratio=0, vslam_particle_filter.sampleSize=50");
	EXPECT_EQ(plan.variations[1].label(), "vslam_mixture_proposal.dual_ratio=0, vslam_particle_filter.sampleSize=100");
	EXPECT_EQ(plan.variations[5].label(), "vslam_mixture_proposal.dual_ratio=0.2, vslam_particle_filter.sampleSize=100");
	const std::string last = plan.variations[5].name;
	ASSERT_EQ(plan.tasks.size(), 24u);  // fixed data: no rendering
	EXPECT_EQ(plan.tasks[0].id, "run/demo/" + plan.variations[0].name + "/seed1");
	EXPECT_EQ(plan.tasks[23].id, "run/demo/" + last + "/seed7");
	EXPECT_EQ(plan.tasks[23].dir, dir.file("out/demo/" + last + "/seed7"));  // relative to the batch file
	EXPECT_GE(plan.jobs, 1);  // 0: one per core
}

TEST(BatchPlan, AVariationKeepsItsFolderWhenTheGridGrows)
{
	TempDir dir;
	const auto small = loadBatchPlan(writeBatch(dir, "seeds = 1", "[grid]\nvslam_particle_filter.sampleSize = 50 100\n"));
	const auto grown = loadBatchPlan(writeBatch(dir, "seeds = 1",
		"[grid]\nvslam_particle_filter.sampleSize = 100 50 200\nvslam_mixture_proposal.dual_ratio = 0.1\n"));
	const auto none = loadBatchPlan(writeBatch(dir, "seeds = 1", ""));
	ASSERT_EQ(small.variations.size(), 2u);
	ASSERT_EQ(none.variations.size(), 1u);
	EXPECT_EQ(none.variations[0].name, "defaults");
	EXPECT_NE(small.variations[0].name, small.variations[1].name);
	EXPECT_EQ(small.variations[0].name.size(), 9u);  // "v" + 8 hex digits
	// The same settings keep their folder whatever the grid's order; other
	// settings (here every variation of the grown grid has a new key) get
	// other folders.
	const auto again = loadBatchPlan(writeBatch(dir, "seeds = 1", "[grid]\nvslam_particle_filter.sampleSize = 100 50\n"));
	EXPECT_EQ(again.variations[0].name, small.variations[1].name);
	EXPECT_EQ(again.variations[1].name, small.variations[0].name);
	for (const auto& v : grown.variations)
		for (const auto& w : small.variations) EXPECT_NE(v.name, w.name) << v.label();
}

TEST(BatchPlan, SimulatedScenariosAreRenderedOncePerSeedBeforeAnyRun)
{
	TempDir dir;
	const auto plan = loadBatchPlan(writeBatch(dir, "seeds = 1 2",
		"[scenario:room]\nsimul_ini = " + kSource + "/config_ini/simul_demo.ini\nsimul_set = vslam_simul.duration=20\n"
			"vslam_ini = " + kSource + "/config_ini/demo_rendered.ini\n[grid]\nvslam_particle_filter.sampleSize = 50 100\n"));
	ASSERT_EQ(plan.tasks.size(), 2u + 2 * 2 * 2);
	EXPECT_EQ(plan.tasks[0].id, "render/room/seed1");
	EXPECT_EQ(plan.tasks[1].id, "render/room/seed2");
	for (size_t i = 2; i < plan.tasks.size(); i++) EXPECT_EQ(plan.tasks[i].kind, Task::Kind::Run);
	const Scenario& room = plan.scenarios[1];
	EXPECT_EQ(plan.rawlogOf(room, 2), dir.file("out/room/data_seed2/sim.rawlog"));
	EXPECT_EQ(room.simulSet, (std::vector<std::string>{"vslam_simul.duration=20"}));
}

TEST(BatchPlan, MistakesAreConfigErrorsNamingTheSectionAndKey)
{
	TempDir dir;
	const auto expectError = [&](const std::string& batchSection, const std::string& rest, const std::string& what) {
		const std::string e = errorOf(writeBatch(dir, batchSection, rest));
		EXPECT_NE(e.find(what), std::string::npos) << "expected '" << what << "' in: " << e;
	};
	expectError("seeds = 1\nsed = 3", "", "[batch] sed: unknown key (did you mean 'set'?)");
	expectError("seeds = 1", "[grids]\n", "unknown section [grids]");
	expectError("seeds = 3-1", "", "'3-1' is not a seed");
	expectError("seeds = 1 1", "", "a seed is given twice");
	expectError("seeds = 1\njobs = many", "", "[batch] jobs = 'many': not an integer");
	expectError("seeds = 1", "[scenario:other]\nrawlog = nowhere.rawlog\n", "[scenario:other] rawlog: no file");
	expectError("seeds = 1", "[scenario:other]\nground_truth = " + kSource + "/rawlogs/demo_visual_groundtruth.tum\n",
		"give either simul_ini or rawlog");
	// vslam's own checks, before anything runs: a misspelt key in the grid.
	expectError("seeds = 1", "[grid]\nvslam_particle_filter.sampleSise = 50 100\n", "sampleSise");
	expectError("seeds = 1", "[grid]\nvslam_particle_filter.sampleSize = 50 -3\n", "sampleSize=-3");
}

TEST(BatchPlan, OverridesChangeTheFilesKeysWithoutACopyOfIt)
{
	TempDir dir;
	const std::string file = writeBatch(dir, "seeds = 1 2",
		"[grid]\nvslam_particle_filter.sampleSize = 50 100\nvslam_mixture_proposal.dual_ratio = 0 0.1\n");
	// One grid axis replaced, one left out, one added; the seeds and the
	// output folder changed; a relative path is the caller's, not the file's.
	const auto plan = loadBatchPlan(file, {"grid.vslam_particle_filter.sampleSize=200", "grid.vslam_mixture_proposal.dual_ratio=",
		"grid.vslam_kidnap.enabled=false true", "batch.seeds=3", "batch.output_dir=elsewhere/out"});
	ASSERT_EQ(plan.variations.size(), 2u);
	EXPECT_EQ(plan.variations[0].label(), "vslam_kidnap.enabled=false, vslam_particle_filter.sampleSize=200");
	EXPECT_EQ(plan.variations[1].label(), "vslam_kidnap.enabled=true, vslam_particle_filter.sampleSize=200");
	EXPECT_EQ(plan.seeds, (std::vector<int>{3}));
	EXPECT_EQ(plan.outputDir, (std::filesystem::current_path() / "elsewhere/out").string());
	EXPECT_EQ(plan.overrides.back(), "batch.output_dir=" + plan.outputDir);  // what a listed task carries
	// Without overrides the file is read as it is; of two overrides of one
	// key the later wins.
	EXPECT_EQ(loadBatchPlan(file).variations.size(), 4u);
	const std::string dropped = "grid.vslam_mixture_proposal.dual_ratio=", set = dropped + "0.3";
	EXPECT_EQ(loadBatchPlan(file, {dropped, set}).variations[0].label(),
		"vslam_mixture_proposal.dual_ratio=0.3, vslam_particle_filter.sampleSize=50");
	EXPECT_EQ(loadBatchPlan(file, {set, dropped}).variations[0].label(), "vslam_particle_filter.sampleSize=50");
	// The same variation, the same folder, whether it comes from the file or
	// from an override.
	const auto fromFile = loadBatchPlan(writeBatch(dir, "seeds = 1",
		"[grid]\nvslam_kidnap.enabled = true\nvslam_particle_filter.sampleSize = 200\n"));
	EXPECT_EQ(fromFile.variations[0].name, plan.variations[1].name);
}

TEST(BatchPlan, AnOverrideNamingWhatTheFileDoesNotHaveIsAnError)
{
	TempDir dir;
	const std::string file = writeBatch(dir, "seeds = 1", "[grid]\nvslam_particle_filter.sampleSize = 50 100\n");
	const auto errorWith = [&](const std::string& override) {
		try
		{
			loadBatchPlan(file, {override});
		}
		catch (const vslam::ConfigError& e)
		{
			return std::string(e.what());
		}
		return std::string();
	};
	EXPECT_NE(errorWith("batch.ouput_dir=x").find("[batch] ouput_dir: unknown key (did you mean 'output_dir'?)"),
		std::string::npos);
	EXPECT_NE(errorWith("btach.seeds=2").find("has no section [btach]"), std::string::npos);
	EXPECT_NE(errorWith("scenario:dmeo.set=vslam.max_steps=10").find("has no section [scenario:dmeo]"), std::string::npos);
	EXPECT_NE(errorWith("grid.vslam_kidnap.enabled=").find("no such key in batch '" + file + "', [grid]"),
		std::string::npos);
	EXPECT_NE(errorWith("grid.vslam_particle_filter.sampleSise=50").find("sampleSise"), std::string::npos);
	EXPECT_NE(errorWith("seeds=2").find("malformed override 'seeds=2'"), std::string::npos);
}

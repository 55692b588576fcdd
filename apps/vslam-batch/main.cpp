/** vslam-batch: INI-driven experiment batches (doc/experiments.md).
 *
 *   vslam-batch BATCH.ini [--jobs N]       run every task here, then the summary
 *   vslam-batch BATCH.ini --list-tasks     one shell command per task, renders
 *                                          first: for a cluster's job array
 *   vslam-batch BATCH.ini --task ID        run one task (what a listed line does)
 *   vslam-batch BATCH.ini --slurm DIR [--submit]
 *                                          the batch as Slurm job arrays (SlurmSubmission.h)
 *   vslam-batch BATCH.ini --summary        the summary of what is done so far
 *
 * Each also takes --set SECTION.KEY=VALUE (repeatable): a change to the
 * batch file's keys (loadBatchPlan), carried into every listed command.
 */
#include <libvslam/batch/BatchPlan.h>
#include <libvslam/batch/BatchRunner.h>
#include <libvslam/batch/BatchSummary.h>
#include <libvslam/batch/BatchTask.h>
#include <libvslam/batch/ListedTasks.h>
#include <libvslam/batch/SlurmSubmission.h>
#include <libvslam/config/ConfigError.h>

#include <filesystem>
#include <iostream>
#include <string>

namespace
{
const char* kUsage =
	"Usage: vslam-batch BATCH.ini [--jobs N]    run the batch here (resumes), then the summary\n"
	"       vslam-batch BATCH.ini --list-tasks  print one command per task (renders first)\n"
	"       vslam-batch BATCH.ini --task ID     run one task\n"
	"       vslam-batch BATCH.ini --summary     write the summary of the finished runs\n"
	"       vslam-batch BATCH.ini --slurm DIR [--submit]\n"
	"                                           write the batch as Slurm job arrays into DIR\n"
	"                                           (submit.sh, tasks.txt; [slurm] keys: resources),\n"
	"                                           and with --submit submit them with sbatch\n"
	"Each takes --set SECTION.KEY=VALUE (repeatable) to change a key of the batch file:\n"
	"  --set 'grid.vslam_prefilter.max_Slope=0.02 0.1'  a grid axis, added or replaced\n"
	"  --set grid.KEY=                                 a grid axis left out\n"
	"  --set batch.output_dir=DIR                      (paths relative to the current folder)\n"
	"The batch file names scenarios, seeds and a grid of vslam settings; see\n"
	"config_ini/batches/ and doc/experiments.md. Outputs: OUTPUT_DIR/<scenario>/<variation>/seed<N>/,\n"
	"OUTPUT_DIR/summary.{md,csv} and summary_ate.png.\n"
	"Exit codes: 0 ok, 1 usage, 2 batch or vslam configuration error, 3 some task or the submission failed.\n";

/** The command line. A mistake throws std::invalid_argument. */
struct Arguments
{
	std::string batchFile, taskId, slurmDir, mode = "run";
	bool submit = false, help = false;
	std::vector<std::string> overrides;
	int jobs = -1;  //!< --jobs, or -1
};

Arguments parseArguments(int argc, const char** argv)
{
	Arguments args;
	for (int i = 1; i < argc; i++)
	{
		const std::string a = argv[i];
		const bool hasValue = i + 1 < argc;
		if (a == "--help" || a == "-h")
			args.help = true;
		else if (a == "--list-tasks" || a == "--summary")
			args.mode = a.substr(2);
		else if (a == "--task" && hasValue)
			args.mode = "task", args.taskId = argv[++i];
		else if (a == "--slurm" && hasValue)
			args.mode = "slurm", args.slurmDir = argv[++i];
		else if (a == "--submit")
			args.submit = true;
		else if (a == "--set" && hasValue)
			args.overrides.push_back(argv[++i]);
		else if (a == "--jobs" && hasValue)
		{
			const std::string n = argv[++i];
			if (n.empty() || n.find_first_not_of("0123456789") != std::string::npos || n.size() > 4)
				throw std::invalid_argument("--jobs needs a whole number, not '" + n + "'");
			args.jobs = std::stoi(n);
		}
		else if (a.rfind("--", 0) == 0 || !args.batchFile.empty())
			throw std::invalid_argument("unexpected argument '" + a + "'");
		else
			args.batchFile = a;
	}
	if (args.submit && args.mode != "slurm") throw std::invalid_argument("--submit goes with --slurm DIR");
	return args;
}

/** Runs the batch here (mode "run") or only writes its summary; exit 3 if a task failed. */
int runOrSummarize(const vslam::batch::BatchPlan& plan, const std::string& mode, const std::string& binDir)
{
	using namespace vslam::batch;
	BatchOutcome outcome;
	if (mode == "run")
	{
		std::cout << "vslam-batch: " << plan.tasks.size() << " tasks (" << plan.scenarios.size() << " scenarios, "
				  << plan.variations.size() << " variations, " << plan.seeds.size() << " seeds), " << plan.jobs
				  << " at a time -> " << plan.outputDir << "\n";
		outcome = runBatch(plan, binDir, [](const std::string& line) { std::cout << line << std::endl; });
	}
	std::cout << "\n" << writeBatchSummary(plan) << "\nvslam-batch: " << plan.outputDir << "/summary.md, summary.csv, summary_ate.png";
	if (mode == "run")
		std::cout << "; " << outcome.done << " run, " << outcome.skipped << " done before, " << outcome.failed << " failed";
	std::cout << "\n";
	return outcome.failed ? 3 : 0;
}

/** What the mode does with the loaded plan; the exit code. */
int runMode(const Arguments& args, const vslam::batch::BatchPlan& plan, const std::string& binDir)
{
	using namespace vslam::batch;
	if (args.mode == "list-tasks")
	{
		for (const auto& line : listedTaskCommands(plan, binDir)) std::cout << line << "\n";
		return 0;
	}
	if (args.mode == "slurm")
	{
		const SlurmSubmission submission = writeSlurmSubmission(plan, binDir, args.slurmDir);
		std::cout << submission.describe();
		if (args.submit) submitSlurmSubmission(submission, std::cout);
		return 0;
	}
	if (args.mode == "task")
	{
		const Task* t = plan.find(args.taskId);
		if (!t)
		{
			std::cerr << "vslam-batch: error: no task '" << args.taskId << "' in " << args.batchFile
					  << " (see --list-tasks)\n";
			return 1;
		}
		const TaskOutcome r = runTask(plan, *t, binDir);
		std::cout << t->id << ": " << (r.ok ? "" : "FAILED: ") << r.message << "\n";
		return r.ok ? 0 : 3;
	}
	return runOrSummarize(plan, args.mode, binDir);
}
}  // namespace

int main(int argc, const char** argv)
{
	Arguments args;
	try
	{
		args = parseArguments(argc, argv);
	}
	catch (const std::invalid_argument& e)
	{
		std::cerr << "vslam-batch: error: " << e.what() << "\n" << kUsage;
		return 1;
	}
	if (args.help)
	{
		std::cout << kUsage;
		return 0;
	}
	if (args.batchFile.empty())
	{
		std::cerr << kUsage;
		return 1;
	}
	try
	{
		vslam::batch::BatchPlan plan = vslam::batch::loadBatchPlan(args.batchFile, args.overrides);
		if (args.jobs > 0) plan.jobs = args.jobs;
		const std::string binDir = std::filesystem::canonical("/proc/self/exe").parent_path().string();
		std::filesystem::create_directories(plan.outputDir);
		return runMode(args, plan, binDir);
	}
	catch (const vslam::ConfigError& e)
	{
		std::cerr << "vslam-batch: error: " << e.what() << "\n";
		return 2;
	}
	catch (const std::exception& e)
	{
		std::cerr << "vslam-batch: error: " << e.what() << "\n";
		return 3;
	}
}

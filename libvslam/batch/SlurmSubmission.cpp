#include <libvslam/batch/BatchTask.h>
#include <libvslam/batch/ListedTasks.h>
#include <libvslam/batch/SlurmSubmission.h>
#include <libvslam/io/COutputFile.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace vslam::batch
{
namespace
{
constexpr int kDefaultMaxArraySize = 1001;  // Slurm's own default
constexpr int kDefaultMemMiB = 4096, kDefaultMinutes = 120;
constexpr int kSummaryMemMiB = 2048, kSummaryMinutes = 30;

/** Runs a shell command; its standard output, and its exit status in \a status. */
std::string commandOutput(const std::string& command, int& status)
{
	std::string out;
	FILE* p = popen(command.c_str(), "r");
	if (!p)
	{
		status = -1;
		return out;
	}
	char buffer[4096];
	for (size_t n; (n = fread(buffer, 1, sizeof buffer, p)) > 0;) out.append(buffer, n);
	status = pclose(p);
	return out;
}

void writeFile(const std::string& file, const std::string& text, bool executable)
{
	COutputFile out(file, COutputFile::Mode::Atomic);
	out.write(text);
	out.commit();
	if (executable)
		fs::permissions(file, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
			fs::perm_options::add);
}

/** The sbatch options every job of the submission shares. */
std::string commonOptions(const TSlurmOptions& s)
{
	std::string o;
	if (!s.partition.empty()) o += " --partition=" + shellWord(s.partition);
	if (!s.account.empty()) o += " --account=" + shellWord(s.account);
	for (const auto& extra : s.sbatchOptions) o += " " + shellWord(extra);
	return o;
}

std::string resources(int cpus, int memMiB, int minutes)
{
	return " --cpus-per-task=" + std::to_string(cpus) + " --mem=" + std::to_string(memMiB) + "M --time=" +
		std::to_string(minutes);
}

std::string taskScript(const std::string& dir)
{
	return "#!/bin/bash\n"
		   "# One array element of a vslam-batch submission (vslam-batch --slurm): the\n"
		   "# task on line $1 + SLURM_ARRAY_TASK_ID of tasks.txt.\n"
		   "set -euo pipefail\n"
		   "tasks=" + shellWord(dir + "/tasks.txt") + "\n"
		   "line=$(( $1 + SLURM_ARRAY_TASK_ID ))\n"
		   "command=$(sed -n \"${line}p\" \"$tasks\")\n"
		   "[[ -n \"$command\" ]] || { echo \"task.sh: no line $line in $tasks\" >&2; exit 2; }\n"
		   "echo \"$(date -Is) $(hostname), ${SLURM_CPUS_PER_TASK:-all} CPUs: $command\"\n"
		   "exec bash -c \"$command\"\n";
}

/** The start of submit.sh: where it works, and how it calls sbatch. */
std::string submitScriptHeader(const std::string& batchFile, const std::string& dir)
{
	return "#!/bin/bash\n"
		   "# Submits the vslam batch " + fs::absolute(batchFile).string() + " to Slurm (written by\n"
		   "# vslam-batch --slurm). Per scenario: its renderings' arrays, then its runs'\n"
		   "# (after all its renderings succeeded; a failed rendering cancels them instead\n"
		   "# of leaving them pending); then the summary when every run has ended.\n"
		   "# Job ids: jobs.txt; logs: logs/.\n"
		   "set -euo pipefail\n"
		   "cd " + shellWord(dir) + "\n"
		   "submit() { sbatch --parsable \"$@\" | cut -d ';' -f 1; }\n"
		   ": > jobs.txt\n"
		   "runs=\n";
}

/** The sbatch calls of one array of tasks cut into chunks: each job id is
 * recorded in jobs.txt and appended to the shell variable \a ids
 * (":id:id", for the dependencies of what comes next). */
std::string submitArrays(const std::string& name, const std::string& ids, const std::string& options,
	const std::vector<std::pair<size_t, size_t>>& chunks, int throttle)
{
	std::string s;
	for (const auto& [first, count] : chunks)
	{
		const std::string array = "0-" + std::to_string(count - 1) + (throttle > 0 ? "%" + std::to_string(throttle) : "");
		s += "id=$(submit --job-name=" + shellWord("vslam-" + name) + " --array=" + array + options +
			" --output=" + shellWord("logs/" + name + "_%A_%a.out") + " task.sh " + std::to_string(first) + ")\n";
		s += "echo " + shellWord(name) + "\" $id\" >> jobs.txt\n" + ids + "=\"$" + ids + ":$id\"\n";
	}
	return s;
}
}  // namespace

SlurmNeeds slurmNeeds(const BatchPlan& plan, const std::vector<Task::Kind>& kinds)
{
	const TSlurmOptions& s = plan.slurm;
	double peakMiB = 0, wallSeconds = 0;
	size_t measured = 0;
	for (const auto& task : plan.tasks)
	{
		if (std::find(kinds.begin(), kinds.end(), task.kind) == kinds.end()) continue;
		const Metrics m = readMetrics(task.dir + "/metrics.txt");
		if (!m.count("peak_mib") || !m.count("wall_s") || !std::isfinite(m.at("peak_mib") + m.at("wall_s"))) continue;
		peakMiB = std::max(peakMiB, m.at("peak_mib"));
		wallSeconds = std::max(wallSeconds, m.at("wall_s"));
		measured++;
	}
	SlurmNeeds needs;
	needs.memMiB = measured ? int(std::ceil((1.5 * peakMiB + 256) / 64) * 64) : kDefaultMemMiB;
	needs.timeMinutes = measured ? int(std::ceil(2 * wallSeconds / 60)) + 5 : kDefaultMinutes;
	needs.basis = measured ? "measured on " + std::to_string(measured) + " finished tasks" : "default: nothing measured yet";
	if (s.memMiB > 0) needs.memMiB = s.memMiB;
	if (s.timeMinutes > 0) needs.timeMinutes = s.timeMinutes;
	if (s.memMiB > 0 && s.timeMinutes > 0) needs.basis = "configured";
	return needs;
}

std::vector<std::pair<size_t, size_t>> arrayChunks(size_t first, size_t count, int maxArraySize)
{
	const size_t size = size_t(std::max(1, maxArraySize));
	std::vector<std::pair<size_t, size_t>> chunks;
	for (size_t done = 0; done < count; done += size) chunks.emplace_back(first + done, std::min(size, count - done));
	return chunks;
}

int clusterMaxArraySize()
{
	int status = 0;
	std::istringstream lines(commandOutput("scontrol show config 2>/dev/null", status));
	for (std::string line; std::getline(lines, line);)
	{
		std::istringstream words(line);
		std::string key, equals;
		int value = 0;
		if (words >> key >> equals >> value && key == "MaxArraySize" && equals == "=" && value > 0) return value;
	}
	return kDefaultMaxArraySize;
}

std::string SlurmSubmission::describe() const
{
	std::ostringstream o;
	o << "vslam-batch: Slurm submission in " << dir << ": " << renderings << " renderings, " << runs << " runs in "
	  << arrays << " job arrays (MaxArraySize " << maxArraySize << ")\n";
	if (renderings)
		o << "  per rendering: " << renderNeeds.memMiB << " MiB, " << renderNeeds.timeMinutes << " min ("
		  << renderNeeds.basis << ")\n";
	o << "  per run: " << runNeeds.memMiB << " MiB, " << runNeeds.timeMinutes << " min (" << runNeeds.basis << ")\n";
	o << "  submit with: bash " << dir << "/submit.sh (or vslam-batch ... --slurm DIR --submit)\n";
	return o.str();
}

SlurmSubmission writeSlurmSubmission(const BatchPlan& plan, const std::string& binDir, const std::string& dir)
{
	SlurmSubmission sub;
	sub.dir = fs::absolute(dir).lexically_normal().string();
	fs::create_directories(sub.dir + "/logs");
	const TSlurmOptions& s = plan.slurm;
	sub.maxArraySize = s.maxArraySize > 0 ? s.maxArraySize : clusterMaxArraySize();
	sub.renderings = size_t(std::count_if(plan.tasks.begin(), plan.tasks.end(), [](const Task& t) { return t.kind == Task::Kind::Render; }));
	sub.runs = plan.tasks.size() - sub.renderings;
	sub.renderNeeds = slurmNeeds(plan, {Task::Kind::Render});
	sub.runNeeds = slurmNeeds(plan, {Task::Kind::Peer, Task::Kind::Run});

	const std::vector<std::string> commands = listedTaskCommands(plan, binDir);
	const std::string common = commonOptions(s);
	const std::string renderOptions = common + resources(s.cpusPerTask, sub.renderNeeds.memMiB, sub.renderNeeds.timeMinutes);
	const std::string runOptions = common + resources(s.cpusPerTask, sub.runNeeds.memMiB, sub.runNeeds.timeMinutes);
	std::string tasks, script = submitScriptHeader(plan.batchFile, sub.dir);
	// tasks.txt holds each scenario's renderings, then its other tasks, so
	// that a scenario's runs wait for its own renderings only.
	size_t line = 1;
	for (size_t scenario = 0; scenario < plan.scenarios.size(); scenario++)
	{
		std::vector<std::string> renders, runs;
		for (size_t i = 0; i < plan.tasks.size(); i++)
			if (plan.tasks[i].scenario == scenario)
				(plan.tasks[i].kind == Task::Kind::Render ? renders : runs).push_back(commands[i]);
		for (const auto& command : renders) tasks += command + "\n";
		for (const auto& command : runs) tasks += command + "\n";
		const std::string name = plan.scenarios[scenario].name;
		const auto renderChunks = arrayChunks(line, renders.size(), sub.maxArraySize);
		const auto runChunks = arrayChunks(line + renders.size(), runs.size(), sub.maxArraySize);
		line += renders.size() + runs.size();
		sub.arrays += renderChunks.size() + runChunks.size();
		script += "renders=\n" + submitArrays(name + "-render", "renders", renderOptions, renderChunks, s.throttle);
		const std::string after = renders.empty() ? "" : " --dependency=afterok$renders --kill-on-invalid-dep=yes";
		script += submitArrays(name + "-run", "runs", after + runOptions, runChunks, s.throttle);
	}
	script += "id=$(submit --job-name=vslam-summary --dependency=afterany$runs" + common +
		resources(1, kSummaryMemMiB, kSummaryMinutes) + " --output=logs/summary_%j.out summary.sh)\n"
		"echo \"summary $id\" >> jobs.txt\n"
		"cat jobs.txt\n";
	writeFile(sub.dir + "/tasks.txt", tasks, false);
	writeFile(sub.dir + "/task.sh", taskScript(sub.dir), true);
	writeFile(sub.dir + "/summary.sh", "#!/bin/bash\n# The summary of a vslam-batch submission (vslam-batch --slurm).\nexec " +
		batchCommandLine(plan, binDir) + " --summary\n", true);
	writeFile(sub.dir + "/submit.sh", script, true);
	return sub;
}

void submitSlurmSubmission(const SlurmSubmission& submission, std::ostream& log)
{
	int status = 0;
	commandOutput("command -v sbatch >/dev/null 2>&1", status);
	if (status != 0) throw std::runtime_error("sbatch is not on the PATH: is this a Slurm submission host?");
	const std::string output = commandOutput("bash " + shellWord(submission.dir + "/submit.sh") + " 2>&1", status);
	log << output;
	if (status != 0)
		throw std::runtime_error(submission.dir + "/submit.sh failed (exit " +
			std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + "); jobs submitted so far are in " +
			submission.dir + "/jobs.txt");
}
}  // namespace vslam::batch

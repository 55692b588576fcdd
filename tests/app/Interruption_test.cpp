/** A run stopped part-way (Ctrl-C, SIGTERM, or killed outright) leaves
 * parseable outputs covering every step it processed. Each case starts the
 * built vslam on a long simulated rawlog, waits until the per-step log shows
 * a chosen number of steps, sends the signal, and reads what is on disk. */
#include <gtest/gtest.h>
#include <libvslam/app/RunSummary.h>
#include <libvslam/io/Trajectory.h>
#include <tests/support/RunCommand.h>
#include <tests/support/TempDir.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

using namespace vslam;
using vslam::testing::readFile;
using vslam::testing::lineCount;
using vslam::testing::quoted;
using vslam::testing::runCommand;
using vslam::testing::TempDir;
namespace fs = std::filesystem;

namespace
{
const std::string kSource = VSLAM_SOURCE_DIR;
const std::string kBin = std::string(VSLAM_BINARY_DIR) + "/bin/";

/** A simulated range-bearing rawlog long enough to be interrupted (30,000 steps). */
std::string longRawlog(const TempDir& dir)
{
	const std::string file = dir.file("long.rawlog");
	const auto r = runCommand(quoted(kBin + "vslam-simul-measurements") + " " +
		quoted(kSource + "/config_ini/simul_range_bearing.ini") + " " + quoted(file) +
		" --set vslam_sim.duration=3000");
	EXPECT_EQ(r.exitCode, 0) << r.output;
	return file;
}

struct StoppedRun
{
	int exitCode = -1;  //!< exit status, or -1 if killed by a signal
	int signal = 0;	 //!< the signal that killed it, if any
	bool finishedFirst = false;	 //!< the run ended before the signal was sent
};

/** Runs vslam, sends `sig` once the step log has at least `steps` rows. */
StoppedRun runAndStop(const std::string& rawlog, const std::string& out, size_t steps, int sig)
{
	const std::string ini = kSource + "/config_ini/kfslam_demo_range_bearing.ini";
	const pid_t pid = fork();
	if (pid == 0)
	{
		const std::string vslam = kBin + "vslam";
		const std::string log = out + ".log";
		if (!std::freopen(log.c_str(), "w", stdout) || !std::freopen(log.c_str(), "a", stderr))
			_exit(127);
		// What is checked is how outputs end, not the estimate: 20 particles
		// instead of the INI's 200, and no loop-closure graph (its solves make
		// this 30,000-step run 13x slower), keep these runs (55,000 steps in
		// the kill test) short, under the sanitizers above all.
		execl(vslam.c_str(), vslam.c_str(), ini.c_str(), rawlog.c_str(), "--out", out.c_str(), "--quiet", "--set",
			"vslam_particle_filter.sampleSize=20", "--set", "vslam_loop_closure.enabled=false",
			static_cast<char*>(nullptr));
		_exit(127);
	}
	StoppedRun r;
	int status = 0;
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
	while (std::chrono::steady_clock::now() < deadline)
	{
		if (waitpid(pid, &status, WNOHANG) == pid)
		{
			r.finishedFirst = true;
			break;
		}
		if (lineCount(out + "/log_filter_steps.txt") > steps + 1)  // two header lines
		{
			kill(pid, sig);
			break;
		}
		std::this_thread::sleep_for(std::chrono::milliseconds(1));
	}
	if (!r.finishedFirst)
	{
		if (std::chrono::steady_clock::now() >= deadline) kill(pid, SIGKILL);
		waitpid(pid, &status, 0);
	}
	if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
	if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
	return r;
}

/** Both path files parse, have the same steps 0..n-1 with increasing
 * times, and n >= minSteps; returns n. */
size_t checkPaths(const std::string& out, size_t minSteps)
{
	const Trajectory rbpf = readRbpfSlamPath(out + "/log_estimated_path.txt");
	const Trajectory tum = readTrajectory(out + "/estimated_path.tum");
	EXPECT_GE(rbpf.size(), minSteps);
	// The two files are flushed one after the other: a hard kill may land between them.
	EXPECT_LE(std::max(rbpf.size(), tum.size()) - std::min(rbpf.size(), tum.size()), 1u);
	for (size_t i = 0; i < rbpf.size(); i++)
	{
		EXPECT_EQ(rbpf[i].step, static_cast<long>(i));
		if (i > 0)
		{
			EXPECT_GT(rbpf[i].t, rbpf[i - 1].t);
		}
		if (i < tum.size())
		{
			EXPECT_DOUBLE_EQ(tum[i].t, rbpf[i].t);
		}
	}
	return rbpf.size();
}
}  // namespace

TEST(Interruption, SigintAndSigtermEndCleanlyWithTheSummaryOfWhatWasDone)
{
	TempDir dir;
	const std::string rawlog = longRawlog(dir);
	int n = 0, stopped = 0;
	for (const int sig : {SIGINT, SIGTERM})
		for (const size_t steps : {50, 2000, 9000})
		{
			const std::string out = dir.file("o" + std::to_string(n++));
			const StoppedRun r = runAndStop(rawlog, out, steps, sig);
			if (r.finishedFirst) continue;  // a very fast machine: nothing to check
			stopped++;
			EXPECT_EQ(r.exitCode, 130) << readFile(out + ".log");
			const size_t done = checkPaths(out, steps);
			const std::string summary = readFile(out + "/run_summary.yaml");
			EXPECT_NE(summary.find("status: interrupted"), std::string::npos) << summary;
			EXPECT_EQ(summaryNumber(vslam::readRunSummary(out + "/run_summary.yaml"), "rawlog.steps"), done)
				<< "paths have " << done << " steps\n"
				<< summary;
			EXPECT_EQ(lineCount(out + "/log_odometry_path.txt"), done);
		}
	EXPECT_GE(stopped, 4) << "runs ended before the signal: the test checked too little";
}

TEST(Interruption, KilledRunsLeaveParseableOutputsUpToTheKill)
{
	TempDir dir;
	const std::string rawlog = longRawlog(dir);
	int n = 0, stopped = 0;
	for (const size_t steps : {1, 10, 100, 500, 1000, 3000, 6000, 10000, 15000, 20000})
	{
		const std::string out = dir.file("k" + std::to_string(n++));
		const StoppedRun r = runAndStop(rawlog, out, steps, SIGKILL);
		if (r.finishedFirst) continue;
		stopped++;
		EXPECT_EQ(r.signal, SIGKILL);
		checkPaths(out, steps);
		// The per-step log's rows are whole too, but for the last one if the
		// kill cut its write: then it has no newline (a write that crosses a
		// page of the file can be cut by SIGKILL), and readers skip it.
		std::ifstream f(out + "/log_filter_steps.txt");
		std::string line;
		size_t rows = 0;
		while (std::getline(f, line))
		{
			if (line.rfind('%', 0) == 0) continue;  // the header lines
			std::istringstream in(line);
			double v;
			int columns = 0;
			while (in >> v) columns++;
			if (f.eof() && columns != 13) break;  // the unterminated last row
			EXPECT_EQ(columns, 13) << "row " << rows << ": '" << line << "'";
			rows++;
		}
		EXPECT_GE(rows, steps);
	}
	EXPECT_GE(stopped, 7) << "runs ended before the kill: the test checked too little";
}

TEST(Interruption, ARerunIntoTheFolderOfAKilledRunHoldsOnlyItsOwnOutputs)
{
	TempDir dir;
	const std::string rawlog = longRawlog(dir);
	const std::string out = dir.file("o");
	// A first run that completes, then one killed in the same folder.
	const std::string ini = kSource + "/config_ini/kfslam_demo_range_bearing.ini";
	const auto first = runCommand(quoted(kBin + "vslam") + " " + quoted(ini) + " " + quoted(rawlog) + " --out " + quoted(out) +
		" --quiet --set vslam_particle_filter.sampleSize=20 --set vslam.max_steps=300");
	ASSERT_EQ(first.exitCode, 0) << first.output;
	const std::string firstId = vslam::readRunSummary(out + "/run_summary.yaml")["run_id"].as<std::string>();
	const StoppedRun killed = runAndStop(rawlog, out, 1000, SIGKILL);
	if (killed.finishedFirst) GTEST_SKIP() << "the run ended before the kill";
	const auto summary = vslam::readRunSummary(out + "/run_summary.yaml");
	EXPECT_EQ(summary["status"].as<std::string>(), "running") << "the killed run's own summary";
	const std::string killedId = summary["run_id"].as<std::string>();
	EXPECT_NE(killedId, firstId);
	// Nothing of the completed run is left to pass for the killed one's.
	for (const char* f : {"final_map.txt", "most_likely_path.txt", "most_likely_path.tum", "pose_graph_path.tum"})
		EXPECT_FALSE(fs::exists(out + "/" + f)) << f;
	EXPECT_NE(readFile(out + "/estimated_path.tum").find(killedId), std::string::npos);
	EXPECT_GT(checkPaths(out, 1000), 300u);
	// The rerun completes and names itself everywhere.
	const auto rerun = runCommand(quoted(kBin + "vslam") + " " + quoted(ini) + " " + quoted(rawlog) + " --out " + quoted(out) +
		" --quiet --set vslam_particle_filter.sampleSize=20 --set vslam.max_steps=200");
	ASSERT_EQ(rerun.exitCode, 0) << rerun.output;
	const std::string rerunId = vslam::readRunSummary(out + "/run_summary.yaml")["run_id"].as<std::string>();
	for (const char* f : {"estimated_path.tum", "final_map.txt", "log_filter_steps.txt", "config_used.ini"})
		EXPECT_NE(readFile(out + "/" + f).find(rerunId), std::string::npos) << f;
	EXPECT_EQ(checkPaths(out, 200), 200u);
}

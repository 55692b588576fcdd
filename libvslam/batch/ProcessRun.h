#pragma once
/** \file ProcessRun.h
 * Runs a program as a child process with its output to a log file, and
 * measures what the batch tables report: exit status, wall time and peak
 * resident memory (the child's own, from wait4). */
#include <string>
#include <vector>

namespace vslam::batch
{
struct ProcessResult
{
	int exitCode = -1;  //!< -1 if it did not start
	int signal = 0;  //!< the signal that ended it, or 0
	double wallSeconds = 0;
	double peakMiB = 0;
	bool ok() const { return exitCode == 0 && signal == 0; }
	std::string describe() const;  //!< "exit 3", "killed by signal 9", ...
};

/** Runs argv[0] (a path) with argv, stdout and stderr appended to logFile,
 * stdin from /dev/null; waits for it. */
ProcessResult runProcess(const std::vector<std::string>& argv, const std::string& logFile);
}  // namespace vslam::batch

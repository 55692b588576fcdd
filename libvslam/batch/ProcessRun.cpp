#include <fcntl.h>
#include <libvslam/batch/ProcessRun.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <cerrno>
#include <chrono>
#include <csignal>

extern char** environ;

namespace vslam::batch
{
std::string ProcessResult::describe() const
{
	if (exitCode == -1 && signal == 0) return "could not start";
	if (signal) return "killed by signal " + std::to_string(signal);
	return "exit " + std::to_string(exitCode);
}

ProcessResult runProcess(const std::vector<std::string>& args, const std::string& logFile)
{
	ProcessResult r;
	std::vector<char*> argv;
	for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
	argv.push_back(nullptr);
	posix_spawn_file_actions_t files;
	posix_spawn_file_actions_init(&files);
	posix_spawn_file_actions_addopen(&files, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
	posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, logFile.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
	posix_spawn_file_actions_adddup2(&files, STDOUT_FILENO, STDERR_FILENO);
	const auto start = std::chrono::steady_clock::now();
	pid_t pid = 0;
	const int spawned = posix_spawn(&pid, argv[0], &files, nullptr, argv.data(), environ);
	posix_spawn_file_actions_destroy(&files);
	if (spawned != 0) return r;
	int status = 0;
	rusage usage{};
	while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR)
	{
	}
	r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	r.peakMiB = double(usage.ru_maxrss) / 1024.0;  // KiB on Linux
	if (WIFSIGNALED(status))
		r.signal = WTERMSIG(status);
	else
		r.exitCode = WEXITSTATUS(status);
	return r;
}
}  // namespace vslam::batch

#include <fcntl.h>
#include <libvslam/core/InputError.h>
#include <libvslam/io/CRawlogReader.h>
#include <libvslam/io/IsolatedRawlogCheck.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fstream>
#include <new>

// With a sanitizer runtime linked in, a fuzzer or the tests may have set a
// death callback (libFuzzer saves the input as a finding): the child must not
// run it. Without a sanitizer the symbol is absent (weak, null).
extern "C" void __sanitizer_set_death_callback(void (*)(void)) __attribute__((weak));

namespace vslam
{
namespace
{
// The child's messages, 8 bytes each: the index of the entry it is about to
// read, or one of these markers.
constexpr uint64_t kFinished = ~uint64_t(0);
constexpr uint64_t kOutOfMemory = ~uint64_t(0) - 1;

void send(int fd, uint64_t value)
{
	const char* p = reinterpret_cast<const char*>(&value);
	size_t left = sizeof value;
	while (left > 0)
	{
		const ssize_t n = ::write(fd, p, left);
		if (n < 0 && errno == EINTR) continue;
		if (n <= 0) ::_exit(3);
		p += n;
		left -= size_t(n);
	}
}

[[noreturn]] void readInChild(const std::string& rawlogFile, int fd)
{
	// Only the child's own outcome counts: no handler inherited from the
	// parent (the app's Ctrl-C flag, a fuzzer's crash reporter) acts for it,
	// and nothing it prints reaches the user.
	for (int sig : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL, SIGTERM, SIGALRM})
		std::signal(sig, SIG_DFL);
	std::signal(SIGINT, SIG_IGN);  // Ctrl-C is the parent's to handle
	if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(nullptr);
	const int devNull = ::open("/dev/null", O_WRONLY);
	if (devNull >= 0)
	{
		::dup2(devNull, STDOUT_FILENO);
		::dup2(devNull, STDERR_FILENO);
	}
	try
	{
		CRawlogReader reader(rawlogFile, std::nullopt);
		reader.scanObjects([fd](size_t entry) { send(fd, entry); });
	}
	catch (const std::bad_alloc&)
	{
		send(fd, kOutOfMemory);
		::_exit(0);
	}
	catch (...)
	{
		// An ordinary read error: the parent's own reading reports it.
	}
	send(fd, kFinished);
	::_exit(0);  // no destructors, no exit handlers of the parent's copy
}

uint64_t residentBytes(pid_t pid)
{
	std::ifstream statm("/proc/" + std::to_string(pid) + "/statm");
	uint64_t sizePages = 0, residentPages = 0;
	statm >> sizePages >> residentPages;
	return residentPages * uint64_t(::sysconf(_SC_PAGESIZE));
}

/** What the parent learnt while watching the child. */
struct ChildReport
{
	uint64_t lastEntry = 0;
	bool finished = false, outOfMemory = false;
	std::string killedBecause;
};

ChildReport watchChild(pid_t child, int fd, const TIsolatedReadOptions& limits)
{
	using Clock = std::chrono::steady_clock;
	ChildReport report;
	const uint64_t memoryLimit = residentBytes(::getpid()) + limits.maxBytesPerEntry;
	auto lastProgress = Clock::now();
	std::string pending;
	for (;;)
	{
		pollfd p{fd, POLLIN, 0};
		const int ready = ::poll(&p, 1, 20 /* ms */);
		if (ready < 0 && errno != EINTR) break;
		if (ready > 0)
		{
			char chunk[4096];
			const ssize_t n = ::read(fd, chunk, sizeof chunk);
			if (n < 0 && errno == EINTR) continue;
			if (n <= 0) break;  // the child has ended
			pending.append(chunk, size_t(n));
			for (; pending.size() >= 8; pending.erase(0, 8))
			{
				uint64_t value = 0;
				std::memcpy(&value, pending.data(), 8);
				if (value == kFinished)
					report.finished = true;
				else if (value == kOutOfMemory)
					report.outOfMemory = true;
				else
				{
					report.lastEntry = value;
					lastProgress = Clock::now();
				}
			}
		}
		if (residentBytes(child) > memoryLimit)
			report.killedBecause = "reading it needs more than " +
				std::to_string(limits.maxBytesPerEntry >> 20) + " MiB of memory (a corrupt count inside the object)";
		else if (std::chrono::duration<double>(Clock::now() - lastProgress).count() > limits.maxSecondsPerEntry)
			report.killedBecause = "reading it did not end within " +
				std::to_string(int(limits.maxSecondsPerEntry)) + " s (a corrupt count inside the object)";
		if (!report.killedBecause.empty())
		{
			::kill(child, SIGKILL);
			break;
		}
	}
	return report;
}
}  // namespace

std::optional<UnreadableEntry> findUnreadableEntry(const std::string& rawlogFile, const TIsolatedReadOptions& limits)
{
	int fds[2];
	if (::pipe2(fds, O_CLOEXEC) != 0)
		throw InputError("rawlog '" + rawlogFile + "': cannot start the process that checks it: " + std::strerror(errno));
	const pid_t child = ::fork();
	if (child < 0)
	{
		::close(fds[0]);
		::close(fds[1]);
		throw InputError("rawlog '" + rawlogFile + "': cannot start the process that checks it: " + std::strerror(errno));
	}
	if (child == 0)
	{
		::close(fds[0]);
		readInChild(rawlogFile, fds[1]);
	}
	::close(fds[1]);
	const ChildReport report = watchChild(child, fds[0], limits);
	::close(fds[0]);
	int status = 0;
	while (::waitpid(child, &status, 0) < 0 && errno == EINTR)
	{
	}
	if (report.finished && report.killedBecause.empty()) return std::nullopt;

	UnreadableEntry bad;
	bad.entry = size_t(report.lastEntry);
	if (!report.killedBecause.empty())
		bad.why = report.killedBecause;
	else if (report.outOfMemory)
		bad.why = "reading it runs out of memory (a corrupt count inside the object)";
	else if (WIFSIGNALED(status))
		bad.why = std::string("MRPT's deserializer crashed on it (") + ::strsignal(WTERMSIG(status)) + ")";
	else
		bad.why = "the process reading it ended with exit code " + std::to_string(WEXITSTATUS(status));
	return bad;
}
}  // namespace vslam

#include <libvslam/core/AllottedCpus.h>

#include <opencv2/core.hpp>

#include <sched.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace vslam
{
namespace
{
/** SLURM_CPUS_PER_TASK as a positive count, or 0 if unset or not a number. */
int slurmCpusPerTask()
{
	const char* text = std::getenv("SLURM_CPUS_PER_TASK");
	if (!text || !*text) return 0;
	char* end = nullptr;
	const long n = std::strtol(text, &end, 10);
	return *end == '\0' && n > 0 && n < 1 << 20 ? int(n) : 0;
}
}  // namespace

int allottedCpus()
{
	cpu_set_t mask;
	CPU_ZERO(&mask);
	int cpus = sched_getaffinity(0, sizeof mask, &mask) == 0 ? CPU_COUNT(&mask) : 0;
	if (cpus <= 0) cpus = std::max(1, cv::getNumberOfCPUs());
	const int slurm = slurmCpusPerTask();
	return slurm > 0 ? std::min(cpus, slurm) : cpus;
}

void useOnlyAllottedCpus() { cv::setNumThreads(std::min(cv::getNumThreads(), allottedCpus())); }
}  // namespace vslam

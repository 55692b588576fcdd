/** allottedCpus follows the affinity mask and SLURM_CPUS_PER_TASK; OpenCV's pool is capped by it. */
#include <gtest/gtest.h>
#include <libvslam/core/AllottedCpus.h>

#include <opencv2/core.hpp>

#include <sched.h>

#include <cstdlib>
#include <string>

namespace
{
/** Sets an environment variable for one scope, then restores it. */
class ScopedEnv
{
   public:
	ScopedEnv(const char* name, const char* value) : m_name(name)
	{
		if (const char* old = std::getenv(name)) m_old = old, m_had = true;
		value ? setenv(name, value, 1) : unsetenv(name);
	}
	~ScopedEnv() { m_had ? setenv(m_name, m_old.c_str(), 1) : unsetenv(m_name); }

   private:
	const char* m_name;
	std::string m_old;
	bool m_had = false;
};

int affinityCount()
{
	cpu_set_t mask;
	CPU_ZERO(&mask);
	sched_getaffinity(0, sizeof mask, &mask);
	return CPU_COUNT(&mask);
}
}  // namespace

TEST(AllottedCpus, AreTheAffinityMaskWithoutSlurm)
{
	ScopedEnv unset("SLURM_CPUS_PER_TASK", nullptr);
	EXPECT_EQ(vslam::allottedCpus(), affinityCount());
}

TEST(AllottedCpus, SlurmsCpusPerTaskLimitsThemAndNonsenseIsIgnored)
{
	{
		ScopedEnv one("SLURM_CPUS_PER_TASK", "1");
		EXPECT_EQ(vslam::allottedCpus(), 1);
		const int before = cv::getNumThreads();
		cv::setNumThreads(4);
		vslam::useOnlyAllottedCpus();
		EXPECT_EQ(cv::getNumThreads(), 1);
		cv::setNumThreads(before);
	}
	{
		ScopedEnv many("SLURM_CPUS_PER_TASK", "4096");  // more than the mask: the mask wins
		EXPECT_EQ(vslam::allottedCpus(), affinityCount());
	}
	for (const char* bad : {"", "two", "-3", "0", "2x"})
	{
		ScopedEnv nonsense("SLURM_CPUS_PER_TASK", bad);
		EXPECT_EQ(vslam::allottedCpus(), affinityCount()) << "SLURM_CPUS_PER_TASK='" << bad << "'";
	}
}

TEST(AllottedCpus, FollowANarrowerAffinityMask)
{
	cpu_set_t all, one;
	CPU_ZERO(&all);
	ASSERT_EQ(sched_getaffinity(0, sizeof all, &all), 0);
	int first = 0;
	while (!CPU_ISSET(first, &all)) first++;
	CPU_ZERO(&one);
	CPU_SET(first, &one);
	ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
	ScopedEnv unset("SLURM_CPUS_PER_TASK", nullptr);
	const int n = vslam::allottedCpus();
	sched_setaffinity(0, sizeof all, &all);
	EXPECT_EQ(n, 1);
}

TEST(AllottedCpus, ASmallerOpenCvPoolStays)
{
	ScopedEnv unset("SLURM_CPUS_PER_TASK", nullptr);
	const int before = cv::getNumThreads();
	cv::setNumThreads(1);
	vslam::useOnlyAllottedCpus();
	EXPECT_EQ(cv::getNumThreads(), 1);
	cv::setNumThreads(before);
}

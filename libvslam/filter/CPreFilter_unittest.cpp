#include <gtest/gtest.h>
#include <libvslam/config/ConfigError.h>
#include <libvslam/filter/CPreFilter.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cmath>
#include <limits>

using namespace vslam;
using V = CPreFilter::Verdict;

TEST(CPreFilter, DefaultsArePapersButASlopeForAKnownMount)
{
	const CPreFilter pf;
	EXPECT_EQ(pf.check(3.0, 10, 0.02), V::Accepted);  // boundaries accepted
	EXPECT_EQ(pf.check(3.01, 50, 0.0), V::RejectedProjErrRMS);
	EXPECT_EQ(pf.check(1.0, 9, 0.0), V::RejectedNPoints);
	EXPECT_EQ(pf.check(1.0, 50, 0.021), V::RejectedSlope);
	EXPECT_EQ(pf.check(1.0, 50, -0.021), V::RejectedSlope);
}

TEST(CPreFilter, FirstViolatedRuleInThePapersOrder)
{
	const CPreFilter pf;
	EXPECT_EQ(pf.check(5.0, 2, 1.0), V::RejectedProjErrRMS);
	EXPECT_EQ(pf.check(1.0, 2, 1.0), V::RejectedNPoints);
}

TEST(CPreFilter, NaNStatisticsAreRejected)
{
	const CPreFilter pf;
	EXPECT_EQ(pf.check(std::nan(""), 50, 0), V::RejectedProjErrRMS);
	EXPECT_EQ(pf.check(1.0, 50, std::nan("")), V::RejectedSlope);
}

TEST(CPreFilter, ConfigurableRegion)
{
	mrpt::config::CConfigFileMemory c("[p]\nmax_ProjErrRMS = 5\nmin_NPoints = 4\nmax_Slope = 0.3\n");
	CPreFilter pf;
	pf.options.loadFromConfigFile(c, "p");
	EXPECT_EQ(pf.check(5.0, 4, 0.3), V::Accepted);
	EXPECT_EQ(pf.check(4.0, 5, 0.31), V::RejectedSlope);
	mrpt::config::CConfigFileMemory bad("[p]\nmin_NPoints = -1\n");
	EXPECT_THROW(pf.options.loadFromConfigFile(bad, "p"), ConfigError);
	mrpt::config::CConfigFileMemory negativeSlope("[p]\nmax_Slope = -0.1\n");
	EXPECT_THROW(pf.options.loadFromConfigFile(negativeSlope, "p"), ConfigError);
}

#include <gtest/gtest.h>
#include <libvslam/config/ConfigError.h>
#include <libvslam/filter/CPreFilter.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cmath>
#include <limits>

using namespace vslam;
using V = CPreFilter::Verdict;

TEST(CPreFilter, PaperDefaults)
{
	const CPreFilter pf;
	EXPECT_EQ(pf.check(3.0, 10, 0.1, 0), V::Accepted);  // boundaries accepted
	EXPECT_EQ(pf.check(3.01, 50, 0.0, 0), V::RejectedProjErrRMS);
	EXPECT_EQ(pf.check(1.0, 9, 0.0, 0), V::RejectedNPoints);
	EXPECT_EQ(pf.check(1.0, 50, 0.11, 0), V::RejectedSlope);
	EXPECT_EQ(pf.check(1.0, 50, -0.11, 0), V::RejectedSlope);
}

TEST(CPreFilter, FirstViolatedRuleInThePapersOrder)
{
	const CPreFilter pf;
	EXPECT_EQ(pf.check(5.0, 2, 1.0, 0), V::RejectedProjErrRMS);
	EXPECT_EQ(pf.check(1.0, 2, 1.0, 0), V::RejectedNPoints);
}

TEST(CPreFilter, NaNStatisticsAreRejected)
{
	const CPreFilter pf;
	EXPECT_EQ(pf.check(std::nan(""), 50, 0, 0), V::RejectedProjErrRMS);
	EXPECT_EQ(pf.check(1.0, 50, std::nan(""), 0), V::RejectedSlope);
}

TEST(CPreFilter, HeightIsCheckedOnlyWhenConfigured)
{
	CPreFilter pf;
	EXPECT_EQ(pf.check(1.0, 50, 0.0, 3.0), V::Accepted);  // the paper's region has no height rule
	pf.options.max_Height = 0.1;
	EXPECT_EQ(pf.check(1.0, 50, 0.0, 0.1), V::Accepted);
	EXPECT_EQ(pf.check(1.0, 50, 0.0, -0.1), V::Accepted);
	EXPECT_EQ(pf.check(1.0, 50, 0.0, 0.11), V::RejectedHeight);
	EXPECT_EQ(pf.check(1.0, 50, 0.0, -0.11), V::RejectedHeight);
	EXPECT_EQ(pf.check(1.0, 50, 0.0, std::nan("")), V::RejectedHeight);
	EXPECT_EQ(pf.check(1.0, 50, 0.2, 0.5), V::RejectedSlope);  // the paper's rules first
}

TEST(CPreFilter, ConfigurableRegion)
{
	mrpt::config::CConfigFileMemory c(
		"[p]\nmax_ProjErrRMS = 5\nmin_NPoints = 4\nmax_Slope = 0.3\nmax_Height = 0.05\n");
	CPreFilter pf;
	pf.options.loadFromConfigFile(c, "p");
	EXPECT_EQ(pf.check(4.0, 5, 0.2, 0.05), V::Accepted);
	EXPECT_EQ(pf.check(4.0, 5, 0.2, 0.06), V::RejectedHeight);
	mrpt::config::CConfigFileMemory bad("[p]\nmin_NPoints = -1\n");
	EXPECT_THROW(pf.options.loadFromConfigFile(bad, "p"), ConfigError);
	mrpt::config::CConfigFileMemory negativeHeight("[p]\nmax_Height = -0.1\n");
	EXPECT_THROW(pf.options.loadFromConfigFile(negativeHeight, "p"), ConfigError);
}

TEST(CPreFilter, SlopeStdWidensTheSlopeOnlyWithAFactor)
{
	CPreFilter pf;
	EXPECT_EQ(pf.check(1.0, 50, 0.05, 0, 0.04), V::Accepted);  // the paper's rule: |Slope| alone
	pf.options.Slope_std_factor = 1;
	EXPECT_EQ(pf.check(1.0, 50, 0.05, 0, 0.05), V::Accepted);  // 0.05 + 0.05 on the bound
	EXPECT_EQ(pf.check(1.0, 50, -0.05, 0, 0.06), V::RejectedSlope);
	EXPECT_EQ(pf.check(1.0, 50, 0.0, 0, std::numeric_limits<double>::infinity()), V::RejectedSlope);
	EXPECT_EQ(pf.check(1.0, 50, 0.09, 0, 0), V::Accepted);  // not known: |Slope| alone
	pf.options.Slope_std_factor = 2;
	EXPECT_EQ(pf.check(1.0, 50, 0.05, 0, 0.03), V::RejectedSlope);
	mrpt::config::CConfigFileMemory c("[p]\nSlope_std_factor = 1.5\n");
	pf.options.loadFromConfigFile(c, "p");
	EXPECT_EQ(pf.options.Slope_std_factor, 1.5);
	mrpt::config::CConfigFileMemory negative("[p]\nSlope_std_factor = -1\n");
	EXPECT_THROW(pf.options.loadFromConfigFile(negative, "p"), ConfigError);
}

TEST(CPreFilter, KidnapEvidenceIsASecondTierWithinTheAcceptedRegion)
{
	CPreFilter pf;
	EXPECT_TRUE(pf.isKidnapEvidence(0.09));  // off: every accepted measurement
	pf.options.evidence_max_Slope = 0.02;
	EXPECT_TRUE(pf.isKidnapEvidence(0.02));
	EXPECT_TRUE(pf.isKidnapEvidence(-0.02));
	EXPECT_FALSE(pf.isKidnapEvidence(0.021));
	EXPECT_FALSE(pf.isKidnapEvidence(std::nan("")));
	EXPECT_EQ(pf.check(1.0, 50, 0.05, 0), V::Accepted);  // still accepted for the particles
	pf.options.Slope_std_factor = 1;  // the same upper limit as the region's
	EXPECT_TRUE(pf.isKidnapEvidence(0.01, 0.01));
	EXPECT_FALSE(pf.isKidnapEvidence(0.01, 0.011));
	mrpt::config::CConfigFileMemory negative("[p]\nevidence_max_Slope = -0.1\n");
	EXPECT_THROW(pf.options.loadFromConfigFile(negative, "p"), ConfigError);
}

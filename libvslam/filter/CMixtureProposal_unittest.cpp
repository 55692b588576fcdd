#include <gtest/gtest.h>
#include <libvslam/filter/CMixtureProposal.h>

using namespace vslam;

TEST(CMixtureProposal, DynamicRatioRisesAsTheExplainedFractionFalls)
{
	CMixtureProposal m;
	m.options.dual_ratio = 0.1;
	m.options.dual_ratio_max = 0.5;
	EXPECT_DOUBLE_EQ(m.ratio(1.0, true), 0.1);
	EXPECT_DOUBLE_EQ(m.ratio(0.0, true), 0.5);
	EXPECT_DOUBLE_EQ(m.ratio(0.5, true), 0.3);
	m.options.dual_ratio_max = 0.1;  // a fixed share
	EXPECT_DOUBLE_EQ(m.ratio(0.0, true), 0.1);
	EXPECT_DOUBLE_EQ(m.ratio(1.0, true), 0.1);
}

TEST(CMixtureProposal, NoDualsWhenTheyCannotSharpenTheCloud)
{
	CMixtureProposal m;
	EXPECT_EQ(m.ratio(0.2, false), 0.0);
	m.options.dual_only_if_sharper = false;
	EXPECT_GT(m.ratio(0.2, false), 0.0);
}

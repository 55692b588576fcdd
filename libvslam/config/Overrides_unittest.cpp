#include <gtest/gtest.h>
#include <libvslam/config/ConfigError.h>
#include <libvslam/config/Overrides.h>
#include <mrpt/config/CConfigFileMemory.h>

using namespace vslam;
using namespace vslam::config;

TEST(Overrides, ParsesAndApplies)
{
	const Override o = parseOverride("vslam_motion_model.sigma_T = 0.2");
	EXPECT_EQ(o.section, "vslam_motion_model");
	EXPECT_EQ(o.key, "sigma_T");
	EXPECT_EQ(o.value, "0.2");
	mrpt::config::CConfigFileMemory c("[vslam_motion_model]\nsigma_T = 0.1\n");
	applyOverrides(c, {o, parseOverride("vslam.new_key=x=y")});
	EXPECT_EQ(c.read_string("vslam_motion_model", "sigma_T", ""), "0.2");
	EXPECT_EQ(c.read_string("vslam", "new_key", ""), "x=y");
}

TEST(Overrides, RejectsMalformedStrings)
{
	EXPECT_THROW(parseOverride("novalue"), ConfigError);
	EXPECT_THROW(parseOverride("nosection=3"), ConfigError);
	EXPECT_THROW(parseOverride(".key=3"), ConfigError);
	EXPECT_THROW(parseOverride("sec.=3"), ConfigError);
}

// Found by fuzz_config: MRPT throws a plain runtime error for a broken
// $eval{} directive, which escaped the apps' configuration-error handling.
TEST(ParseIniWithOverrides, SyntaxErrorsAreConfigErrors)
{
	EXPECT_THROW(parseIniWithOverrides("[a]\nx = $eval{s =\n", {}), vslam::ConfigError);
	try
	{
		parseIniWithOverrides("[a]\nx = 1\ny = $eval{s =\n", {});
	}
	catch (const vslam::ConfigError& e)
	{
		EXPECT_NE(std::string(e.what()).find("Line 3"), std::string::npos) << e.what();
	}
}

TEST(ParseIniWithOverrides, OverridesAreSeenLikeKeysInTheText)
{
	const auto cfg = parseIniWithOverrides("[a]\nx = 1\n", {{"a", "x", "2"}, {"b", "y", "3"}});
	EXPECT_EQ(cfg.read_int("a", "x", 0), 2);
	EXPECT_TRUE(cfg.keyExists("b", "y"));
	EXPECT_EQ(cfg.read_int("b", "y", 0), 3);
}

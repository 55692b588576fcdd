#include <gtest/gtest.h>
#include <libvslam/config/ConfigError.h>
#include <libvslam/config/KeyValidation.h>
#include <mrpt/config/CConfigFileMemory.h>

using namespace vslam;
using namespace vslam::config;

namespace
{
KnownKeys known()
{
	KnownKeys k;
	k.add("vslam_motion_model", "sigma_T");
	k.add("vslam_motion_model", "sigma_R");
	k.add("vslam_motion_model", "sigma_R_per_meter");
	k.add("vslam", "rawlog_file");
	return k;
}
}  // namespace

TEST(KeyValidation, EditDistance)
{
	EXPECT_EQ(editDistance("sigma_T", "sigma_T"), 0u);
	EXPECT_EQ(editDistance("sigma_T", "SIGMA_t"), 0u);
	EXPECT_EQ(editDistance("sigmaT", "sigma_T"), 1u);
	EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
	EXPECT_EQ(closestMatch("sigma_Rr", {"sigma_T", "sigma_R"}), "sigma_R");
	EXPECT_EQ(closestMatch("completely_else", {"sigma_T"}), "");
}

TEST(KeyValidation, AcceptsKnownKeysCaseInsensitivelyAndForeignSections)
{
	mrpt::config::CConfigFileMemory c(
		"[vslam_motion_model]\nsigma_t = 1\n[MappingApplication]\nfoo = 2\n");
	EXPECT_NO_THROW(checkNoUnknownKeys(c, known()));
}

TEST(KeyValidation, NamesUnknownKeyWithClosestKnownKey)
{
	mrpt::config::CConfigFileMemory c("[vslam_motion_model]\nsigma_TT = 1\n");
	try
	{
		checkNoUnknownKeys(c, known());
		FAIL() << "expected ConfigError";
	}
	catch (const ConfigError& e)
	{
		const std::string msg = e.what();
		EXPECT_NE(msg.find("'sigma_TT'"), std::string::npos) << msg;
		EXPECT_NE(msg.find("[vslam_motion_model]"), std::string::npos) << msg;
		EXPECT_NE(msg.find("did you mean 'sigma_T'"), std::string::npos) << msg;
	}
}

TEST(KeyValidation, NamesUnknownVslamSection)
{
	mrpt::config::CConfigFileMemory c("[vslam_motoin_model]\nsigma_T = 1\n");
	try
	{
		checkNoUnknownKeys(c, known());
		FAIL() << "expected ConfigError";
	}
	catch (const ConfigError& e)
	{
		EXPECT_NE(std::string(e.what()).find("did you mean [vslam_motion_model]"),
				  std::string::npos)
			<< e.what();
	}
}

TEST(KeyValidation, SaysWhereAMovedKeyWentInAnOldSection)
{
	KnownKeys k = known();
	k.addMoved("vslam_frontend", "creation_views", "vslam_landmark_creation", "views");
	mrpt::config::CConfigFileMemory c("[vslam_frontend]\ncreation_views = 4\n");
	try
	{
		checkNoUnknownKeys(c, k);
		FAIL() << "expected ConfigError";
	}
	catch (const ConfigError& e)
	{
		EXPECT_NE(std::string(e.what()).find("'creation_views' of section [vslam_frontend] is now "
											 "[vslam_landmark_creation] views"),
			std::string::npos)
			<< e.what();
	}
	// A key of the old section that never existed is still an unknown section.
	mrpt::config::CConfigFileMemory other("[vslam_frontend]\nno_such_key = 1\n");
	EXPECT_THROW(checkNoUnknownKeys(other, k), ConfigError);
}

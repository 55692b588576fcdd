#include <gtest/gtest.h>
#include <libvslam/config/ConfigReference.h>

using namespace vslam::config;

TEST(ConfigReference, EverySectionIsATableOfKeyDefaultAndMeaning)
{
	const std::string ini =
		"[vslam]\n"
		"rawlog_file               =               // Input rawlog; relative to this INI\n"
		"RANDOM_SEED               =  -1           // Seed (-1: from the clock)\n"
		"\n"
		"[vslam_motion_model]\n"
		"sigma_T                   =  0.050000     // Translational noise | per sqrt(m)\n"
		"slip_std_xy               =  20.000000\n"
		"resamplingMethod          =  prSystematic // a | b\n";
	EXPECT_EQ(markdownReference(ini),
		"\n### [vslam]\n\n| key | default | meaning |\n|---|---|---|\n"
		"| `rawlog_file` |  | Input rawlog; relative to this INI |\n"
		"| `RANDOM_SEED` | `-1` | Seed (-1: from the clock) |\n"
		"\n### [vslam_motion_model]\n\n| key | default | meaning |\n|---|---|---|\n"
		"| `sigma_T` | `0.05` | Translational noise \\| per sqrt(m) |\n"
		"| `slip_std_xy` | `20` |  |\n"
		"| `resamplingMethod` | `prSystematic` | a \\| b |\n");
}

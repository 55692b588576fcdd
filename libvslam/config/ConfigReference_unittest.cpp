#include <gtest/gtest.h>
#include <libvslam/config/ConfigReference.h>

using namespace vslam::config;

TEST(ConfigReference, EverySectionIsATableOfKeyDefaultAllowedValuesAndMeaning)
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
	const std::vector<NumericKey> numbers = {{"vslam", "RANDOM_SEED", Range::closed(-1, 9), true, -1},
		{"vslam_motion_model", "sigma_T", Range::closed(0, 10), false, 0.05},
		{"vslam_motion_model", "slip_std_xy", {0, 100, false, true}, false, 20}};
	EXPECT_EQ(markdownReference(ini, numbers),
		"\n### [vslam]\n| key | default | allowed | meaning |\n|---|---|---|---|\n"
		"| `rawlog_file` |  |  | Input rawlog; relative to this INI |\n"
		"| `RANDOM_SEED` | `-1` | integer in [-1, 9] | Seed (-1: from the clock) |\n"
		"\n### [vslam_motion_model]\n| key | default | allowed | meaning |\n|---|---|---|---|\n"
		"| `sigma_T` | `0.05` | in [0, 10] | Translational noise \\| per sqrt(m) |\n"
		"| `slip_std_xy` | `20` | in (0, 100] |  |\n"
		"| `resamplingMethod` | `prSystematic` |  | a \\| b |\n");
}

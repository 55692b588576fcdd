/** doc/configuration.md is the apps' own reference of their keys
 * (--print-default-config --markdown): regenerate it with
 * scripts/configuration_md.sh when an option changes. */
#include <gtest/gtest.h>
#include <tests/support/RunCommand.h>

#include <string>

using vslam::testing::contains;
using vslam::testing::readFile;
using vslam::testing::runCommand;

TEST(ConfigurationReference, MatchesTheCode)
{
	const std::string doc = readFile(std::string(VSLAM_SOURCE_DIR) + "/doc/configuration.md");
	ASSERT_FALSE(doc.empty()) << "doc/configuration.md is missing";
	for (const char* app : {"vslam", "vslam-simul", "vslam-simul-measurements"})
	{
		const auto r = runCommand(std::string(VSLAM_BINARY_DIR) + "/bin/" + app + " --print-default-config --markdown");
		ASSERT_EQ(r.exitCode, 0) << app << ": " << r.output;
		ASSERT_TRUE(contains(r.output, "| key | default | allowed | meaning |")) << app << ": " << r.output;
		EXPECT_TRUE(contains(doc, r.output)) << "doc/configuration.md does not hold " << app
											 << "'s reference: run scripts/configuration_md.sh";
	}
}

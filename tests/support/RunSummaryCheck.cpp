/** Every run_summary.yaml a test leaves in its TempDir must be YAML that
 * MRPT's parser reads, with a known status: the summaries of runs that
 * failed on corrupt rawlogs, full disks and bad settings included. */
#include <gtest/gtest.h>
#include <libvslam/app/RunSummary.h>
#include <tests/support/TempDir.h>

#include <set>

void vslam::testing::checkRunSummariesUnder(const std::filesystem::path& dir)
{
	static const std::set<std::string> statuses = {"running", "completed", "interrupted", "failed"};
	std::error_code ec;
	for (auto it = std::filesystem::recursive_directory_iterator(dir, ec);
		 !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
	{
		if (it->path().filename() != "run_summary.yaml") continue;
		try
		{
			const auto summary = vslam::readRunSummary(it->path().string());
			const std::string status = summary["status"].as<std::string>();
			EXPECT_TRUE(statuses.count(status)) << it->path() << ": status '" << status << "'";
		}
		catch (const std::exception& e)
		{
			ADD_FAILURE() << "run summary " << it->path() << " does not parse: " << e.what();
		}
	}
}

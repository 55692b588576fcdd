#pragma once
/** \file TempDir.h  A scratch directory removed at the end of a test. */
#include <cstdlib>
#include <filesystem>
#include <string>

namespace vslam::testing
{
/** Checks every run_summary.yaml under `dir`. Linked only into the test
 * binaries that run vslam (tests/support/RunSummaryCheck.cpp), so that every
 * summary the test suite produces is parsed before its folder goes. */
void checkRunSummariesUnder(const std::filesystem::path& dir) __attribute__((weak));

class TempDir
{
   public:
	TempDir()
	{
		std::string tmpl =
			(std::filesystem::temp_directory_path() / "vslam_test_XXXXXX")
				.string();
		if (!::mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
		m_path = tmpl;
	}
	~TempDir()
	{
		if (checkRunSummariesUnder) checkRunSummariesUnder(m_path);
		std::error_code ec;
		std::filesystem::remove_all(m_path, ec);
	}
	TempDir(const TempDir&) = delete;
	TempDir& operator=(const TempDir&) = delete;

	const std::filesystem::path& path() const { return m_path; }
	std::string file(const std::string& name) const
	{
		return (m_path / name).string();
	}

   private:
	std::filesystem::path m_path;
};
}  // namespace vslam::testing

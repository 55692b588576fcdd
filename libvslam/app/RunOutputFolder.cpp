#include <libvslam/app/RunOutputFolder.h>
#include <libvslam/core/OutputError.h>
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <sstream>

using namespace vslam;
namespace fs = std::filesystem;

namespace
{
constexpr const char* kSummarySpace = ".summary_space";
constexpr off_t kSummarySpaceBytes = 32 * 1024;  // a summary takes about 4 KiB
}  // namespace

const std::vector<std::string>& RunOutputFolder::outputNames()
{
	static const std::vector<std::string> names = {"run_summary.yaml", "config_used.ini",
		"log_estimated_path.txt", "estimated_path.tum", "log_odometry_path.txt", "odometry_path.tum",
		"smoothed_path.tum", "log_filter_steps.txt", "final_map.txt", "final_map.vslam", "most_likely_path.txt",
		"most_likely_path.tum", "pose_graph_path.tum", "pose_graph.graph", "final_map.3Dscene", kSummarySpace};
	return names;
}

RunOutputFolder::RunOutputFolder(std::string dir) : m_dir(std::move(dir))
{
	std::error_code ec;
	fs::create_directories(m_dir, ec);
	if (!fs::is_directory(m_dir))
		throw OutputError("cannot create output folder '" + m_dir + "'" + (ec ? ": " + ec.message() : ""));
	if (access(m_dir.c_str(), W_OK | X_OK) != 0)
		throw OutputError("cannot write to output folder '" + m_dir + "': permission denied");
}

void RunOutputFolder::clearEarlierOutputs() const
{
	for (const auto& name : outputNames())
		for (const std::string& candidate : {name, name + ".tmp"})
		{
			std::error_code ec;
			if (!fs::exists(file(candidate), ec)) continue;
			if (!fs::remove(file(candidate), ec))
				throw OutputError("cannot remove the earlier run's '" + file(candidate) + "': " + ec.message());
		}
}

void RunOutputFolder::reserveSummarySpace() const
{
	FILE* f = std::fopen(file(kSummarySpace).c_str(), "wb");
	if (!f) return;
	const bool reserved = posix_fallocate(fileno(f), 0, kSummarySpaceBytes) == 0;
	std::fclose(f);
	if (!reserved) std::remove(file(kSummarySpace).c_str());
}

void RunOutputFolder::releaseSummarySpace() const { std::remove(file(kSummarySpace).c_str()); }

std::string RunOutputFolder::file(const std::string& name) const { return (fs::path(m_dir) / name).string(); }

std::string vslam::makeRunId(const std::string& effectiveConfigText, const std::string& rawlogFile, uint64_t seed)
{
	std::ostringstream what;
	std::error_code ec;
	const auto size = fs::file_size(rawlogFile, ec);
	const auto time = fs::last_write_time(rawlogFile, ec).time_since_epoch().count();
	what << effectiveConfigText << '\n' << fs::absolute(rawlogFile).string() << '\n' << size << '\n' << time << '\n' << seed;
	uint64_t h = 1469598103934665603ull;  // FNV-1a, 64 bits
	for (const unsigned char c : what.str()) h = (h ^ c) * 1099511628211ull;
	char id[17];
	std::snprintf(id, sizeof id, "%016llx", static_cast<unsigned long long>(h));
	return id;
}

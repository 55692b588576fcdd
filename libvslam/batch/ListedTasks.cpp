#include <libvslam/batch/ListedTasks.h>

#include <filesystem>

namespace vslam::batch
{
std::string shellWord(const std::string& s)
{
	std::string q = "'";
	for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
	return q + "'";
}

std::string batchCommandLine(const BatchPlan& plan, const std::string& binDir)
{
	std::string command =
		shellWord(binDir + "/vslam-batch") + " " + shellWord(std::filesystem::absolute(plan.batchFile).string());
	for (const auto& o : plan.overrides) command += " --set " + shellWord(o);
	return command;
}

std::vector<std::string> listedTaskCommands(const BatchPlan& plan, const std::string& binDir)
{
	const std::string command = batchCommandLine(plan, binDir);
	std::vector<std::string> lines;
	for (const auto& t : plan.tasks) lines.push_back(command + " --task " + shellWord(t.id));
	return lines;
}
}  // namespace vslam::batch

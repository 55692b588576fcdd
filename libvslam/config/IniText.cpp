#include <libvslam/config/IniText.h>

namespace vslam::config
{
std::string toIniText(
	const mrpt::config::CLoadableOptions& opts, const std::string& section)
{
	mrpt::config::CConfigFileMemory mem;
	opts.saveToConfigFile(mem, section);
	std::string text;
	mem.getContent(text);
	return text;
}

mrpt::config::CConfigFileMemory toParsedConfig(
	const mrpt::config::CLoadableOptions& opts, const std::string& section)
{
	return mrpt::config::CConfigFileMemory(toIniText(opts, section));
}
}  // namespace vslam::config

#include <libvslam/config/ConfigError.h>
#include <libvslam/config/Overrides.h>

#include <fstream>
#include <sstream>

namespace vslam::config
{
namespace
{
std::string trim(const std::string& s)
{
	const auto b = s.find_first_not_of(" \t");
	if (b == std::string::npos) return {};
	const auto e = s.find_last_not_of(" \t");
	return s.substr(b, e - b + 1);
}
}  // namespace

Override parseOverride(const std::string& text)
{
	const auto eq = text.find('=');
	const auto dot = text.find('.');
	if (eq == std::string::npos || dot == std::string::npos || dot > eq)
		throw ConfigError(
			"malformed override '" + text + "', expected SECTION.KEY=VALUE");
	Override o;
	o.section = trim(text.substr(0, dot));
	o.key = trim(text.substr(dot + 1, eq - dot - 1));
	o.value = trim(text.substr(eq + 1));
	if (o.section.empty() || o.key.empty())
		throw ConfigError(
			"malformed override '" + text + "', expected SECTION.KEY=VALUE");
	return o;
}

void applyOverrides(
	mrpt::config::CConfigFileBase& cfg, const std::vector<Override>& overrides)
{
	for (const auto& o : overrides) cfg.write(o.section, o.key, o.value);
}

}  // namespace vslam::config

namespace
{
void setContentOrThrowConfigError(mrpt::config::CConfigFileMemory& cfg, const std::string& text)
{
	try
	{
		cfg.setContent(text);
	}
	catch (const std::exception& e)
	{
		throw vslam::ConfigError(std::string("INI syntax: ") + e.what());
	}
}
}  // namespace

mrpt::config::CConfigFileMemory vslam::config::parseIniWithOverrides(
	const std::string& iniText, const std::vector<Override>& overrides)
{
	mrpt::config::CConfigFileMemory cfg;
	setContentOrThrowConfigError(cfg, iniText);
	if (overrides.empty()) return cfg;
	applyOverrides(cfg, overrides);
	std::string content;
	cfg.getContent(content);
	setContentOrThrowConfigError(cfg, content);
	return cfg;
}

std::string vslam::config::readIniFile(const std::string& file)
{
	std::ifstream in(file);
	if (!in) throw ConfigError("cannot read configuration file '" + file + "'");
	std::stringstream text;
	text << in.rdbuf();
	return text.str();
}

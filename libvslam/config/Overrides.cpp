#include <libvslam/config/ConfigError.h>
#include <libvslam/config/Overrides.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace vslam::config
{
std::string trim(const std::string& s)
{
	const auto b = s.find_first_not_of(" \t\r");
	if (b == std::string::npos) return {};
	const auto e = s.find_last_not_of(" \t\r");
	return s.substr(b, e - b + 1);
}

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
/** Mistakes MRPT's INI parser lets pass silently, as errors naming the
 * line: binary data (never echoed), keys above the first section (MRPT
 * drops them), a section or a key given twice (MRPT keeps the last). */
void checkIniStructure(const std::string& text)
{
	for (size_t i = 0; i < text.size(); i++)
	{
		const unsigned char c = static_cast<unsigned char>(text[i]);
		if (c < 0x20 && c != '\t' && c != '\n' && c != '\r')
			throw vslam::ConfigError("not an INI text file: binary data at byte " + std::to_string(i));
	}
	std::istringstream lines(text);
	std::string line, section;
	std::map<std::string, int> sections, keys;
	for (int n = 1; std::getline(lines, line); n++)
	{
		const std::string t = vslam::config::trim(line);
		if (t.empty() || t[0] == ';' || t[0] == '#' || t.rfind("//", 0) == 0 || t[0] == '@' || t[0] == '$') continue;
		const std::string where = "line " + std::to_string(n) + ": ";
		if (t[0] == '[')
		{
			section = t.substr(1, t.find(']') - 1);
			if (const auto seen = sections.find(section); seen != sections.end())
				throw vslam::ConfigError(where + "section [" + section + "] is given twice (also line " +
					std::to_string(seen->second) + ")");
			sections[section] = n;
			keys.clear();
			continue;
		}
		const auto eq = t.find('=');
		if (eq == std::string::npos) continue;  // MRPT's parser reports it
		const std::string key = vslam::config::trim(t.substr(0, eq));
		if (section.empty())
			throw vslam::ConfigError(where + "key '" + key + "' is outside any [section]");
		if (const auto seen = keys.find(key); seen != keys.end())
			throw vslam::ConfigError(where + "key '" + key + "' of [" + section + "] is given twice (also line " +
				std::to_string(seen->second) + ")");
		keys[key] = n;
	}
}

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
	checkIniStructure(iniText);
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
	if (std::filesystem::is_directory(file))
		throw ConfigError("configuration file '" + file + "' is a folder, not an INI file");
	std::ifstream in(file);
	if (!in) throw ConfigError("cannot read configuration file '" + file + "'");
	std::stringstream text;
	text << in.rdbuf();
	return text.str();
}

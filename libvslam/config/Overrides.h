#pragma once
/** \file Overrides.h
 * Command-line overrides "SECTION.KEY=VALUE" (vslam --set), so scripts and
 * experiment batches never edit INI files. */
#include <mrpt/config/CConfigFileMemory.h>

#include <string>
#include <vector>

namespace vslam::config
{
struct Override
{
	std::string section, key, value;

	/** "SECTION.KEY=VALUE", as parseOverride() reads it. */
	std::string text() const { return section + "." + key + "=" + value; }
};

/** Parses "SECTION.KEY=VALUE"; throws ConfigError on a malformed string. */
Override parseOverride(const std::string& text);

/** Writes every override into `cfg` (later ones win). */
void applyOverrides(
	mrpt::config::CConfigFileBase& cfg, const std::vector<Override>& overrides);

/** The text of an INI file; ConfigError "cannot read configuration file"
 * naming it if it cannot be read. */
std::string readIniFile(const std::string& file);

/** `s` without leading and trailing blanks. */
std::string trim(const std::string& s);

/** Parses INI text (MRPT syntax, with its @include, $define, $eval{} and
 * ${var} directives), then applies the overrides and parses the result
 * again, so keys written by overrides are seen like keys in the text.
 * Syntax errors, which MRPT throws as plain runtime errors, become
 * ConfigError; so do what MRPT would pass silently: binary data, keys above
 * the first section, a section or a key given twice. */
mrpt::config::CConfigFileMemory parseIniWithOverrides(
	const std::string& iniText, const std::vector<Override>& overrides);

}  // namespace vslam::config

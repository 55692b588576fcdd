#pragma once
/** \file IniText.h
 * Options -> INI text. MRPT's padded write() stores keys that keyExists()
 * does not find until the text is parsed again, so anything that inspects
 * saved options goes through the text. */
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/config/CLoadableOptions.h>

#include <string>

namespace vslam::config
{
/** The INI text of `opts.saveToConfigFile(.., section)`. */
std::string toIniText(
	const mrpt::config::CLoadableOptions& opts, const std::string& section);

/** The same, parsed back into a config object. */
mrpt::config::CConfigFileMemory toParsedConfig(
	const mrpt::config::CLoadableOptions& opts, const std::string& section);
}  // namespace vslam::config

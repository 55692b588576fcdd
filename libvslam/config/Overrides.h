#pragma once
/** \file Overrides.h
 * Command-line overrides "SECTION.KEY=VALUE" (vslam --set), so scripts and
 * experiment batches never edit INI files. */
#include <mrpt/config/CConfigFileBase.h>

#include <string>
#include <vector>

namespace vslam::config
{
struct Override
{
	std::string section, key, value;
};

/** Parses "SECTION.KEY=VALUE"; throws ConfigError on a malformed string. */
Override parseOverride(const std::string& text);

/** Writes every override into `cfg` (later ones win). */
void applyOverrides(
	mrpt::config::CConfigFileBase& cfg, const std::vector<Override>& overrides);

}  // namespace vslam::config

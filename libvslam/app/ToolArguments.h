#pragma once
/** \file ToolArguments.h
 * The command line of vslam's tools: positional arguments, repeatable
 * "--set SECTION.KEY=VALUE" overrides, options that take a value and
 * flags. Anything else starting with "--" is a usage error
 * (std::invalid_argument, exit 1 through runTool). */
#include <libvslam/config/Overrides.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace vslam
{
struct ToolArguments
{
	std::vector<std::string> positional;
	std::vector<config::Override> overrides;
	std::map<std::string, std::string> values;  //!< option -> its value
	std::set<std::string> flags;  //!< flags given

	bool has(const std::string& flag) const { return flags.count(flag) > 0; }
	std::string value(const std::string& option) const
	{
		const auto it = values.find(option);
		return it == values.end() ? std::string() : it->second;
	}
};

/** The finite number \a text given for \a option; throws
 * std::invalid_argument ("OPTION: 'TEXT' is not a number") otherwise. */
double numberArgument(const std::string& option, const std::string& text);

/** valueOptions: e.g. {"--config"}; flags: e.g. {"--quiet", "--help"}
 * ("-h" counts as "--help"). */
ToolArguments parseToolArguments(int argc, const char** argv, const std::set<std::string>& valueOptions,
	const std::set<std::string>& flags);
}  // namespace vslam

#include <libvslam/app/ToolArguments.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace vslam
{
double numberArgument(const std::string& option, const std::string& text)
{
	char* end = nullptr;
	const double v = std::strtod(text.c_str(), &end);
	if (text.empty() || *end != '\0' || !std::isfinite(v))
		throw std::invalid_argument(option + ": '" + text + "' is not a number");
	return v;
}

ToolArguments parseToolArguments(int argc, const char** argv, const std::set<std::string>& valueOptions,
	const std::set<std::string>& flags)
{
	ToolArguments out;
	for (int i = 1; i < argc; i++)
	{
		std::string a = argv[i];
		if (a == "-h") a = "--help";
		if (a == "--set" || valueOptions.count(a))
		{
			if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
			if (a == "--set")
				out.overrides.push_back(config::parseOverride(argv[++i]));
			else
				out.values[a] = argv[++i];
		}
		else if (flags.count(a))
			out.flags.insert(a);
		else if (a.rfind("--", 0) == 0)
			throw std::invalid_argument("unknown option '" + a + "'");
		else
			out.positional.push_back(a);
	}
	return out;
}
}  // namespace vslam

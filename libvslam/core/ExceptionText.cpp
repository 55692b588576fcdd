#include <libvslam/core/ExceptionText.h>

#include <sstream>
#include <vector>

namespace vslam
{
std::string exceptionText(const std::exception& e)
{
	std::istringstream in(e.what());
	std::vector<std::string> parts;
	std::string line;
	bool inStack = false;
	while (std::getline(in, line))
	{
		const auto b = line.find_first_not_of(" \t");
		if (b == std::string::npos) continue;
		line = line.substr(b);
		if (line.rfind("Call stack backtrace", 0) == 0)
		{
			inStack = true;
			continue;
		}
		if (line.rfind("====", 0) == 0 || line.rfind("Original exception", 0) == 0)
		{
			inStack = false;
			continue;
		}
		if (inStack || line.rfind("Location:", 0) == 0 || line.front() == '[') continue;
		if (line.rfind("Message:", 0) == 0) line = line.substr(8);
		const auto b2 = line.find_first_not_of(" \t");
		if (b2 == std::string::npos) continue;
		line = line.substr(b2);
		if (parts.empty() || parts.back() != line) parts.push_back(line);
	}
	if (parts.empty()) return e.what();
	std::string out;
	for (const auto& p : parts) out += (out.empty() ? "" : ": ") + p;
	return out;
}
}  // namespace vslam

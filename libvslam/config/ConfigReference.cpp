#include <libvslam/config/ConfigReference.h>

#include <sstream>

namespace vslam::config
{
namespace
{
std::string trimmed(const std::string& s)
{
	const size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t\r");
	return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

/** A table cell: pipes would end it. */
std::string cell(const std::string& s)
{
	std::string out;
	for (const char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
	return out;
}

/** MRPT writes doubles with six decimals: 0.050000 reads better as 0.05. */
std::string shortNumber(const std::string& v)
{
	if (v.find('.') == std::string::npos || v.find_first_not_of("-+0123456789.") != std::string::npos) return v;
	std::string s = v;
	while (s.back() == '0') s.pop_back();
	if (s.back() == '.') s.pop_back();
	return s;
}
}  // namespace

std::string markdownReference(const std::string& iniText, const std::vector<NumericKey>& numbers)
{
	std::istringstream in(iniText);
	std::ostringstream out;
	std::string line, section;
	const auto allowed = [&](const std::string& key) -> std::string {
		for (const auto& n : numbers)
			if (n.section == section && n.key == key)
				return (n.integer ? "integer " : "") + n.range.describe();
		return "";
	};
	while (std::getline(in, line))
	{
		const std::string t = trimmed(line);
		if (t.empty()) continue;
		if (t.front() == '[' && t.back() == ']')
		{
			section = t.substr(1, t.size() - 2);
			out << "\n### " << t << "\n| key | default | allowed | meaning |\n|---|---|---|---|\n";
			continue;
		}
		const size_t eq = t.find('=');
		if (eq == std::string::npos) continue;
		std::string value = t.substr(eq + 1), meaning;
		if (const size_t slashes = value.find("//"); slashes != std::string::npos)
		{
			meaning = trimmed(value.substr(slashes + 2));
			value = value.substr(0, slashes);
		}
		value = shortNumber(trimmed(value));
		const std::string key = trimmed(t.substr(0, eq));
		out << "| `" << key << "` | " << (value.empty() ? "" : "`" + cell(value) + "`") << " | " << cell(allowed(key))
			<< " | " << cell(meaning) << " |\n";
	}
	return out.str();
}
}  // namespace vslam::config

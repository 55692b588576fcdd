#include <libvslam/config/StrictRead.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace vslam::config
{
namespace
{
std::string trim(const std::string& s)
{
	const auto b = s.find_first_not_of(" \t\r\n");
	if (b == std::string::npos) return {};
	const auto e = s.find_last_not_of(" \t\r\n");
	return s.substr(b, e - b + 1);
}

std::string where(const std::string& section, const std::string& key)
{
	return "[" + section + "] " + key;
}

[[noreturn]] void fail(
	const std::string& section, const std::string& key,
	const std::string& value, const std::string& what)
{
	throw ConfigError(
		where(section, key) + " = '" + value + "': " + what);
}

std::string lower(std::string s)
{
	for (auto& ch : s) ch = static_cast<char>(std::tolower(ch));
	return s;
}

double parseDouble(
	const std::string& section, const std::string& key, const std::string& v)
{
	if (v.empty()) fail(section, key, v, "empty value, expected a number");
	errno = 0;
	char* end = nullptr;
	const double d = std::strtod(v.c_str(), &end);
	if (end == v.c_str() || *end != '\0')
		fail(
			section, key, v,
			"not a number (comments after a value must start with '//')");
	// strtod reads C's hexadecimal numbers; an INI value is decimal.
	if (v.find_first_of("xX") != std::string::npos)
		fail(section, key, v, "not a decimal number");
	if (errno == ERANGE || !std::isfinite(d))
		fail(section, key, v, "not a finite number");
	return d;
}

void checkRange(
	const std::string& section, const std::string& key, const std::string& v,
	double d, const Range& range)
{
	if (!range.contains(d))
		fail(section, key, v, "out of range, must be " + range.describe());
}

thread_local NumericKeyRecorder* activeRecorder = nullptr;
}  // namespace

NumericKeyRecorder::NumericKeyRecorder() : m_outer(activeRecorder) { activeRecorder = this; }
NumericKeyRecorder::~NumericKeyRecorder() { activeRecorder = m_outer; }

void NumericKeyRecorder::record(const NumericKey& key)
{
	if (!activeRecorder) return;
	for (const auto& k : activeRecorder->m_keys)
		if (k.section == key.section && k.key == key.key) return;
	activeRecorder->m_keys.push_back(key);
}

bool Range::contains(double v) const
{
	const bool okLo = loInclusive ? v >= lo : v > lo;
	const bool okHi = hiInclusive ? v <= hi : v < hi;
	return okLo && okHi;
}

std::string Range::describe() const
{
	std::ostringstream s;
	s.precision(12);  // whole integers such as 4294967295
	const bool hasLo = std::isfinite(lo), hasHi = std::isfinite(hi);
	if (hasLo && hasHi)
		s << "in " << (loInclusive ? "[" : "(") << lo << ", " << hi
		  << (hiInclusive ? "]" : ")");
	else if (hasLo)
		s << (loInclusive ? ">= " : "> ") << lo;
	else if (hasHi)
		s << (hiInclusive ? "<= " : "< ") << hi;
	else
		s << "any number";
	return s.str();
}

std::string rawValue(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key)
{
	if (!cfg.keyExists(section, key)) return {};
	const std::string v = trim(cfg.read_string(section, key, "", false));
	// MRPT strips a trailing " // comment" only after a value, so an empty
	// value followed by a comment (as MRPT's own write() produces it) reads
	// back as the comment.
	return v.rfind("//", 0) == 0 ? std::string() : v;
}

double readDouble(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, double defaultValue, const Range& range)
{
	NumericKeyRecorder::record({section, key, range, false, defaultValue});
	if (!cfg.keyExists(section, key)) return defaultValue;
	const std::string v = rawValue(cfg, section, key);
	const double d = parseDouble(section, key, v);
	checkRange(section, key, v, d, range);
	return d;
}

double readDegreesAsRadians(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, double defaultRadians, const Range& rangeDegrees)
{
	return readDouble(
			   cfg, section, key, defaultRadians * 180.0 / M_PI,
			   rangeDegrees) *
		M_PI / 180.0;
}

int64_t readInt(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, int64_t defaultValue, const Range& range)
{
	NumericKeyRecorder::record({section, key, range, true, static_cast<double>(defaultValue)});
	if (!cfg.keyExists(section, key)) return defaultValue;
	const std::string v = rawValue(cfg, section, key);
	if (v.empty()) fail(section, key, v, "empty value, expected an integer");
	errno = 0;
	char* end = nullptr;
	const long long i = std::strtoll(v.c_str(), &end, 10);
	if (end == v.c_str() || *end != '\0' || errno == ERANGE)
		fail(section, key, v, "not an integer");
	checkRange(section, key, v, static_cast<double>(i), range);
	return i;
}

int readCount(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, int defaultValue, double lo, double hi)
{
	return static_cast<int>(readInt(cfg, section, key, defaultValue, Range::closed(lo, hi)));
}

bool readBool(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, bool defaultValue)
{
	if (!cfg.keyExists(section, key)) return defaultValue;
	const std::string v = rawValue(cfg, section, key);
	const std::string l = lower(v);
	if (l == "true" || l == "yes" || l == "1" || l == "on") return true;
	if (l == "false" || l == "no" || l == "0" || l == "off") return false;
	fail(section, key, v, "not a boolean (true/false, yes/no, 1/0)");
}

std::string readString(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, const std::string& defaultValue)
{
	if (!cfg.keyExists(section, key)) return defaultValue;
	return rawValue(cfg, section, key);
}

size_t readChoice(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, size_t defaultIndex,
	const std::vector<std::string>& names)
{
	if (!cfg.keyExists(section, key)) return defaultIndex;
	const std::string v = rawValue(cfg, section, key);
	for (size_t i = 0; i < names.size(); i++)
		if (names[i] == v) return i;
	char* end = nullptr;
	const long idx = std::strtol(v.c_str(), &end, 10);
	if (!v.empty() && *end == '\0' && idx >= 0 &&
		static_cast<size_t>(idx) < names.size())
		return static_cast<size_t>(idx);
	std::string all;
	for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
	fail(section, key, v, "unknown choice, expected one of: " + all);
}

std::string readWord(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, const std::string& defaultValue,
	const std::vector<std::string>& names)
{
	const auto d = std::find(names.begin(), names.end(), defaultValue);
	if (d == names.end())
		throw std::logic_error("readWord: default '" + defaultValue + "' of " + key + " is not a choice");
	return names[readChoice(cfg, section, key, static_cast<size_t>(d - names.begin()), names)];
}

}  // namespace vslam::config

std::vector<double> vslam::config::readNumberList(
	const mrpt::config::CConfigFileBase& c, const std::string& s,
	const std::string& key, const std::vector<double>& def)
{
	if (!c.keyExists(s, key)) return def;
	const std::string v = rawValue(c, s, key);
	std::istringstream in(v);
	std::vector<double> out;
	std::string tok;
	while (in >> tok)
	{
		char* end = nullptr;
		const double d = std::strtod(tok.c_str(), &end);
		if (*end != '\0' || !std::isfinite(d))
			throw ConfigError(
				"[" + s + "] " + key + " = '" + v + "': '" + tok + "' is not a number");
		out.push_back(d);
	}
	return out;
}

std::string vslam::config::joinNumbers(const std::vector<double>& v)
{
	std::ostringstream o;
	for (size_t i = 0; i < v.size(); i++) o << (i ? " " : "") << v[i];
	return o.str();
}

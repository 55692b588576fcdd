#include <libvslam/config/ConfigError.h>
#include <libvslam/config/IniText.h>
#include <libvslam/config/KeyValidation.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <algorithm>
#include <cctype>

namespace vslam::config
{
namespace
{
std::string lower(std::string s)
{
	for (auto& ch : s)
		ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
	return s;
}

bool startsWith(const std::string& s, const std::string& prefix)
{
	return s.size() >= prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
}
}  // namespace

void KnownKeys::addFromOptions(
	const mrpt::config::CLoadableOptions& opts, const std::string& section)
{
	const mrpt::config::CConfigFileMemory mem = toParsedConfig(opts, section);
	std::vector<std::string> ks;
	mem.getAllKeys(section, ks);
	if (ks.empty()) add(section, {});  // a section without keys still exists
	for (const auto& k : ks) add(section, k);
}

void KnownKeys::add(const std::string& section, const std::string& key)
{
	auto& entry = m_sections[lower(section)];
	entry.first = section;
	if (!key.empty() &&
		std::find(entry.second.begin(), entry.second.end(), key) ==
			entry.second.end())
		entry.second.push_back(key);
}

void KnownKeys::addMoved(const std::string& oldSection, const std::string& oldKey, const std::string& newSection,
	const std::string& newKey)
{
	m_moved[lower(oldSection) + "/" + lower(oldKey)] = "[" + newSection + "] " + newKey;
}

std::string KnownKeys::movedTo(const std::string& section, const std::string& key) const
{
	const auto it = m_moved.find(lower(section) + "/" + lower(key));
	return it == m_moved.end() ? std::string() : it->second;
}

bool KnownKeys::hasSection(const std::string& section) const
{
	return m_sections.count(lower(section)) > 0;
}

bool KnownKeys::has(const std::string& section, const std::string& key) const
{
	const auto it = m_sections.find(lower(section));
	if (it == m_sections.end()) return false;
	const std::string lk = lower(key);
	for (const auto& k : it->second.second)
		if (lower(k) == lk) return true;
	return false;
}

std::vector<std::string> KnownKeys::sections() const
{
	std::vector<std::string> out;
	for (const auto& kv : m_sections) out.push_back(kv.second.first);
	return out;
}

std::vector<std::string> KnownKeys::keys(const std::string& section) const
{
	const auto it = m_sections.find(lower(section));
	return it == m_sections.end() ? std::vector<std::string>{}
								  : it->second.second;
}

size_t editDistance(const std::string& a0, const std::string& b0)
{
	const std::string a = lower(a0), b = lower(b0);
	std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
	for (size_t j = 0; j <= b.size(); j++) prev[j] = j;
	for (size_t i = 1; i <= a.size(); i++)
	{
		cur[0] = i;
		for (size_t j = 1; j <= b.size(); j++)
		{
			const size_t subst = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
			cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, subst});
		}
		std::swap(prev, cur);
	}
	return prev[b.size()];
}

std::string closestMatch(
	const std::string& word, const std::vector<std::string>& candidates)
{
	std::string best;
	size_t bestDist = std::numeric_limits<size_t>::max();
	for (const auto& c : candidates)
	{
		const size_t d = editDistance(word, c);
		if (d < bestDist) bestDist = d, best = c;
	}
	// Accept up to about a third of the word wrong (at least 2 edits).
	const size_t tolerance = std::max<size_t>(2, word.size() / 3);
	return bestDist <= tolerance ? best : std::string();
}

namespace
{
/** The error for a key of `section` that is not known there. */
ConfigError unknownKeyError(const KnownKeys& known, const std::string& section, const std::string& key)
{
	const std::string moved = known.movedTo(section, key);
	if (!moved.empty())
		return ConfigError("key '" + key + "' of section [" + section + "] is now " + moved + ": move it there");
	if (!known.hasSection(section))
	{
		const std::string near = closestMatch(section, known.sections());
		return ConfigError(
			"unknown section [" + section + "]" + (near.empty() ? std::string() : " (did you mean [" + near + "]?)"));
	}
	const std::string near = closestMatch(key, known.keys(section));
	return ConfigError("unknown key '" + key + "' in section [" + section + "]" +
		(near.empty() ? std::string(" (no similar key exists)") : " (did you mean '" + near + "'?)"));
}
}  // namespace

void checkNoUnknownKeys(
	const mrpt::config::CConfigFileBase& cfg, const KnownKeys& known,
	const std::string& ownedPrefix)
{
	std::vector<std::string> sections;
	cfg.getAllSections(sections);
	for (const auto& section : sections)
	{
		if (!startsWith(lower(section), lower(ownedPrefix))) continue;
		std::vector<std::string> keys;
		cfg.getAllKeys(section, keys);
		if (!known.hasSection(section) && keys.empty()) throw unknownKeyError(known, section, "");
		for (const auto& key : keys)
			if (!known.has(section, key)) throw unknownKeyError(known, section, key);
	}
}

}  // namespace vslam::config

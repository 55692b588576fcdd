#pragma once
/** \file KeyValidation.h
 * Unknown-key detection for vslam's INI sections: a misspelt key must not
 * silently fall back to its default. The known keys come from the options
 * structs' own saveToConfigFile(), so code, example INI and docs cannot
 * drift apart.
 */
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CLoadableOptions.h>

#include <map>
#include <string>
#include <vector>

namespace vslam::config
{
/** The keys each vslam section accepts (section names as written). */
class KnownKeys
{
   public:
	/** Adds every key that `opts.saveToConfigFile(.., section)` writes. */
	void addFromOptions(
		const mrpt::config::CLoadableOptions& opts, const std::string& section);
	void add(const std::string& section, const std::string& key);

	/** Records that `oldSection`'s `oldKey` is now `newSection`'s `newKey`,
	 * so an INI written for an older version gets told where it went. */
	void addMoved(const std::string& oldSection, const std::string& oldKey, const std::string& newSection,
		const std::string& newKey);
	/** "[new_section] new_key" for a moved key, else "". */
	std::string movedTo(const std::string& section, const std::string& key) const;

	bool hasSection(const std::string& section) const;
	bool has(const std::string& section, const std::string& key) const;
	std::vector<std::string> sections() const;
	std::vector<std::string> keys(const std::string& section) const;

   private:
	/** lower-case section -> (written section name, keys as written) */
	std::map<std::string, std::pair<std::string, std::vector<std::string>>>
		m_sections;
	/** lower-case "section/key" -> "[new_section] new_key" */
	std::map<std::string, std::string> m_moved;
};

/** Throws ConfigError naming the first unknown key (or unknown section) in
 * any section whose name starts with `ownedPrefix` (case-insensitive),
 * together with where it moved or the closest known key. Other sections are left alone, so
 * one INI can also hold e.g. rbpf-slam's sections. */
void checkNoUnknownKeys(
	const mrpt::config::CConfigFileBase& cfg, const KnownKeys& known,
	const std::string& ownedPrefix = "vslam");

/** The candidate closest to `word` by edit distance (case-insensitive), or ""
 * when none is reasonably close. */
std::string closestMatch(
	const std::string& word, const std::vector<std::string>& candidates);

/** Case-insensitive Levenshtein distance. */
size_t editDistance(const std::string& a, const std::string& b);

}  // namespace vslam::config

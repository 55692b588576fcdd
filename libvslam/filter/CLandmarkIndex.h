#pragma once
/** \file CLandmarkIndex.h
 * Landmark key -> slot in every particle's bank. All particles hold the
 * same set of landmarks (creation is driven by the common measurement
 * stream), so the index is kept once per filter, with per-landmark
 * bookkeeping that does not depend on the path hypothesis.
 */
#include <libvslam/models/LandmarkTypes.h>
#include <mrpt/core/Clock.h>

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace vslam
{
class CLandmarkIndex
{
   public:
	struct Entry
	{
		LandmarkKey key;
		mrpt::Clock::time_point created{};
		/** Measurements of this landmark used by the filter. */
		uint64_t measurements = 0;
		uint32_t reinitializations = 0;
		/** Created while the robot was (as found later) kidnapped: its
		 * estimate is re-initialized at its next sighting. */
		bool suspect = false;
	};

	std::optional<size_t> find(const LandmarkKey& key) const
	{
		const auto it = m_slots.find(key);
		if (it == m_slots.end()) return std::nullopt;
		return it->second;
	}

	/** Registers a new landmark; returns its slot (= bank index). */
	size_t add(const LandmarkKey& key, mrpt::Clock::time_point t)
	{
		const size_t slot = m_entries.size();
		m_slots.emplace(key, slot);
		m_entries.push_back(Entry{key, t});
		return slot;
	}

	size_t size() const { return m_entries.size(); }
	template <class F>
	void forEachEntry(F&& f)
	{
		for (auto& e : m_entries) f(e);
	}
	Entry& entry(size_t slot) { return m_entries.at(slot); }
	const Entry& entry(size_t slot) const { return m_entries.at(slot); }

   private:
	std::unordered_map<LandmarkKey, size_t, LandmarkKeyHash> m_slots;
	std::vector<Entry> m_entries;
};
}  // namespace vslam

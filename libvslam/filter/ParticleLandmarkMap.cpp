#include <libvslam/filter/ParticleLandmarkMap.h>

namespace vslam
{
LandmarkMap landmarkMapOf(const CLandmarkIndex& index, const LandmarkBank& bank, std::vector<uint64_t>* measurements)
{
	LandmarkMap map;
	map.reserve(bank.size());
	if (measurements) measurements->clear();
	for (size_t slot = 0; slot < bank.size(); slot++)
	{
		const auto& entry = index.entry(slot);
		map.emplace_back(entry.key, bank[slot]);
		if (measurements) measurements->push_back(entry.measurements);
	}
	return map;
}
}  // namespace vslam

#include <libvslam/app/RunMap.h>
#include <libvslam/io/VSlamMapFile.h>

using namespace vslam;

namespace
{
CVSlamMap::TLandmarkEstimate recordOf(const LandmarkKey& key, const LandmarkEstimate& l, uint64_t measurements)
{
	CVSlamMap::TLandmarkEstimate e;
	e.kind = static_cast<uint8_t>(key.kind);
	e.id = key.id;
	e.mean = {l.mean[0], l.mean[1], l.mean[2]};
	e.cov = {l.cov(0, 0), l.cov(0, 1), l.cov(0, 2), l.cov(1, 1), l.cov(1, 2), l.cov(2, 2)};
	e.updates = l.updates;
	e.measurements = measurements;
	return e;
}
}  // namespace

CVSlamMap vslam::mapOfRun(const CVSlamParticleFilter& filter, const CVisualFrontEnd* frontEnd, const std::string& runId)
{
	CVSlamMap map;
	map.runId = runId;
	const auto& bank = filter.particle(filter.bestParticleIndex()).bank;
	const auto& index = filter.landmarkIndex();
	for (size_t slot = 0; slot < bank.size(); slot++)
	{
		const auto& entry = index.entry(slot);
		map.estimates.push_back(recordOf(entry.key, bank[slot], entry.measurements));
	}
	if (frontEnd) frontEnd->saveMap(map);
	return map;
}

LandmarkMap vslam::estimatesOf(const CVSlamMap& map)
{
	LandmarkMap out;
	for (const auto& e : map.estimates)
	{
		LandmarkEstimate l;
		l.kind = static_cast<LandmarkKind>(e.kind);
		l.mean << e.mean[0], e.mean[1], e.mean[2];
		const auto& c = e.cov;
		l.cov << c[0], c[1], c[2], c[1], c[3], c[4], c[2], c[4], c[5];
		l.updates = e.updates;
		out.push_back({LandmarkKey{l.kind, e.id}, l});
	}
	return out;
}

CVSlamMap vslam::readPriorMap(const std::string& file, double stdXY, double stdPhi)
{
	if (isSerializedFile(file)) return readVSlamMap(file);
	CVSlamMap map;
	std::vector<uint64_t> measurements;
	const LandmarkMap rows = readLandmarkMap(file, stdXY, stdPhi, &measurements);
	for (size_t i = 0; i < rows.size(); i++) map.estimates.push_back(recordOf(rows[i].first, rows[i].second, measurements[i]));
	return map;
}

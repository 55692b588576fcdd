#include <libvslam/obs/CVSlamMap.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <utility>

using namespace vslam;

IMPLEMENTS_SERIALIZABLE(CVSlamMap, mrpt::serialization::CSerializable, vslam)

namespace
{
using mrpt::serialization::CArchive;

/** Elements are read in blocks of this many, so memory follows the data read. */
constexpr uint32_t kReadBlock = 1 << 16;
constexpr uint32_t kMaxTextBytes = 4096;

void readText(CArchive& in, std::string& text, const char* what)
{
	uint32_t n = 0;
	in >> n;
	if (n > kMaxTextBytes)
		throw std::runtime_error(std::string(what) + " of " + std::to_string(n) + " bytes: corrupt data");
	text.resize(n);
	if (n) in.ReadBufferFixEndianness(text.data(), n);
}

/** A vector of `count` plain values, read block by block. */
template <class T>
void readValues(CArchive& in, uint32_t count, std::vector<T>& values)
{
	values.clear();
	for (uint32_t done = 0; done < count;)
	{
		const uint32_t n = std::min(kReadBlock, count - done);
		values.resize(done + n);
		in.ReadBufferFixEndianness(values.data() + done, n);
		done += n;
	}
}

template <class T>
void writeValues(CArchive& out, const std::vector<T>& values)
{
	out << static_cast<uint32_t>(values.size());
	if (!values.empty()) out.WriteBufferFixEndianness(values.data(), values.size());
}

template <class T>
void readVector(CArchive& in, std::vector<T>& values)
{
	uint32_t n = 0;
	in >> n;
	readValues(in, n, values);
}

void writeEstimate(CArchive& out, const CVSlamMap::TLandmarkEstimate& e)
{
	out << e.kind << e.id;
	for (double v : e.mean) out << v;
	for (double v : e.cov) out << v;
	out << e.updates << e.measurements;
}

void readEstimate(CArchive& in, CVSlamMap::TLandmarkEstimate& e)
{
	in >> e.kind >> e.id;
	for (double& v : e.mean) in >> v;
	for (double& v : e.cov) in >> v;
	in >> e.updates >> e.measurements;
}

void writeAppearance(CArchive& out, const CVSlamMap::TLandmarkAppearance& a)
{
	out << a.id;
	std::vector<float> xyz;
	xyz.reserve(3 * a.points.size());
	for (const auto& p : a.points) xyz.insert(xyz.end(), {p.x, p.y, p.z});
	writeValues(out, xyz);
	writeValues(out, a.depthStd);
	out << a.descriptorDepth << a.descriptorCols;
	writeValues(out, a.descriptorBytes);
	out << a.createdAt << a.createdAtOdometry.x << a.createdAtOdometry.y << a.createdAtOdometry.phi;
	out << a.views << a.reprojectionRms << a.recognitions;
	out << a.scaleInformation << a.scaleWeightedSum << a.scalePairsUsed << a.scalePairsRejected;
}

void readAppearance(CArchive& in, CVSlamMap::TLandmarkAppearance& a)
{
	in >> a.id;
	std::vector<float> xyz;
	readVector(in, xyz);
	if (xyz.size() % 3) throw std::runtime_error("point coordinates not in threes: corrupt data");
	a.points.resize(xyz.size() / 3);
	for (size_t i = 0; i < a.points.size(); i++) a.points[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
	readVector(in, a.depthStd);
	in >> a.descriptorDepth >> a.descriptorCols;
	readVector(in, a.descriptorBytes);
	in >> a.createdAt >> a.createdAtOdometry.x >> a.createdAtOdometry.y >> a.createdAtOdometry.phi;
	in >> a.views >> a.reprojectionRms >> a.recognitions;
	in >> a.scaleInformation >> a.scaleWeightedSum >> a.scalePairsUsed >> a.scalePairsRejected;
}

/** Reads `count` records one by one: a corrupt count meets the end of the data. */
template <class T, class Read>
void readRecords(CArchive& in, std::vector<T>& records, Read read)
{
	uint32_t n = 0;
	in >> n;
	records.clear();
	for (uint32_t i = 0; i < n; i++) read(in, records.emplace_back());
}
}  // namespace

uint8_t CVSlamMap::serializeGetVersion() const { return 0; }

void CVSlamMap::serializeTo(CArchive& out) const
{
	out << runId << descriptorStorage << hasCamera;
	if (hasCamera) out << camera;
	out << nextVisualLandmarkId;
	out << static_cast<uint32_t>(estimates.size());
	for (const auto& e : estimates) writeEstimate(out, e);
	out << static_cast<uint32_t>(appearances.size());
	for (const auto& a : appearances) writeAppearance(out, a);
}

void CVSlamMap::serializeFrom(CArchive& in, uint8_t version)
{
	switch (version)
	{
		case 0:
			readText(in, runId, "run ID");
			readText(in, descriptorStorage, "descriptor storage name");
			in >> hasCamera;
			if (hasCamera) in >> camera;
			in >> nextVisualLandmarkId;
			readRecords(in, estimates, readEstimate);
			readRecords(in, appearances, readAppearance);
			break;
		default:
			MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	}
}

namespace
{
bool allFinite(std::initializer_list<double> values)
{
	return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

std::string landmarkName(uint8_t kind, int64_t id)
{
	return std::string(kind == 0 ? "visual" : "point") + " landmark " + std::to_string(id);
}

void validateEstimate(const CVSlamMap::TLandmarkEstimate& e)
{
	if (e.kind > 1) throw std::runtime_error("landmark " + std::to_string(e.id) + " of unknown kind " + std::to_string(e.kind));
	const auto& c = e.cov;
	if (!allFinite({e.mean[0], e.mean[1], e.mean[2], c[0], c[1], c[2], c[3], c[4], c[5]}))
		throw std::runtime_error(landmarkName(e.kind, e.id) + ": a value is not finite");
	// Sylvester's criterion: every leading minor positive (the 2x2 block for a point).
	const double minor2 = c[0] * c[3] - c[1] * c[1];
	const double det3 = c[0] * (c[3] * c[5] - c[4] * c[4]) - c[1] * (c[1] * c[5] - c[4] * c[2]) +
		c[2] * (c[1] * c[4] - c[3] * c[2]);
	if (!(c[0] > 0 && minor2 > 0 && (e.kind == 1 || det3 > 0))) throw std::runtime_error(landmarkName(e.kind, e.id) + ": covariance not positive definite");
}

void validateAppearance(const CVSlamMap::TLandmarkAppearance& a)
{
	const std::string name = landmarkName(0, a.id) + " (appearance)";
	if (a.points.empty()) throw std::runtime_error(name + ": no points");
	for (const auto& p : a.points)
		if (!allFinite({p.x, p.y, p.z})) throw std::runtime_error(name + ": a point is not finite");
	if (!a.depthStd.empty() && a.depthStd.size() != a.points.size())
		throw std::runtime_error(name + ": " + std::to_string(a.depthStd.size()) + " depth stds for " +
			std::to_string(a.points.size()) + " points");
	for (float s : a.depthStd)
		if (!(s >= 0) || !std::isfinite(s)) throw std::runtime_error(name + ": a depth std is negative or not finite");
	const bool depthOk = a.descriptorDepth == CVSlamMap::kBytes || a.descriptorDepth == CVSlamMap::kSignedBytes ||
		a.descriptorDepth == CVSlamMap::kFloats;
	if (!depthOk || a.descriptorCols < 1 || a.descriptorCols > 128)
		throw std::runtime_error(name + ": unknown descriptor storage");
	if (a.descriptorBytes.size() != a.points.size() * a.descriptorCols * a.descriptorValueBytes())
		throw std::runtime_error(name + ": descriptor bytes do not match its points");
	const auto& o = a.createdAtOdometry;
	if (!allFinite({a.createdAt, o.x, o.y, o.phi, a.reprojectionRms}))
		throw std::runtime_error(name + ": a value is not finite");
	if (!(a.scaleInformation > 0 && a.scaleWeightedSum > 0) || !allFinite({a.scaleInformation, a.scaleWeightedSum}))
		throw std::runtime_error(name + ": its scale estimate is not positive and finite");
}
}  // namespace

void CVSlamMap::validate() const
{
	std::set<std::pair<uint8_t, int64_t>> keys;
	for (const auto& e : estimates)
	{
		validateEstimate(e);
		if (!keys.insert({e.kind, e.id}).second) throw std::runtime_error(landmarkName(e.kind, e.id) + " twice");
	}
	std::set<int64_t> seen;
	for (const auto& a : appearances)
	{
		validateAppearance(a);
		if (!keys.count({0, a.id}))
			throw std::runtime_error(landmarkName(0, a.id) + " has an appearance but no estimate");
		if (!seen.insert(a.id).second) throw std::runtime_error(landmarkName(0, a.id) + " has two appearances");
		if (a.id >= nextVisualLandmarkId)
			throw std::runtime_error(landmarkName(0, a.id) + " is not below the next landmark ID");
	}
	if (!appearances.empty() && descriptorStorage.empty())
		throw std::runtime_error("the descriptor storage is not named");
}

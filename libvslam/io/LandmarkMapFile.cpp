#include <libvslam/core/InputError.h>
#include <libvslam/io/COutputFile.h>
#include <libvslam/io/LandmarkMapFile.h>

#include <Eigen/Cholesky>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <unordered_set>
#include <sstream>

namespace vslam
{
namespace
{
std::optional<double> number(const std::string& token)
{
	char* end = nullptr;
	const double v = std::strtod(token.c_str(), &end);
	if (token.empty() || *end != '\0' || !std::isfinite(v)) return std::nullopt;
	return v;
}

std::optional<LandmarkKind> kindOf(const std::string& token)
{
	if (token == "pose") return LandmarkKind::Pose;
	if (token == "point") return LandmarkKind::Point;
	return std::nullopt;
}
}  // namespace

LandmarkMap readLandmarkMap(
	const std::string& file, double stdXY, double stdPhi, std::vector<uint64_t>* measurements)
{
	if (measurements) measurements->clear();
	std::ifstream in(file);
	if (!in) throw InputError("cannot read landmark map '" + file + "'");
	LandmarkMap map;
	std::unordered_set<LandmarkKey, LandmarkKeyHash> seen;
	std::string line;
	for (size_t lineNo = 1; std::getline(in, line); lineNo++)
	{
		std::istringstream is(line);
		std::vector<std::string> tok;
		for (std::string t; is >> t;) tok.push_back(t);
		if (tok.empty() || tok[0][0] == '%' || tok[0][0] == '#') continue;
		const auto bad = [&](const std::string& why) {
			return InputError("landmark map '" + file + "', line " + std::to_string(lineNo) +
				": " + why);
		};
		std::vector<double> v;  // the numbers after id (and kind)
		LandmarkEstimate l;
		const auto kind = tok.size() > 1 ? kindOf(tok[1]) : std::nullopt;
		for (size_t i = kind ? 2 : 1; i < tok.size(); i++)
		{
			const auto x = number(tok[i]);
			if (!x) throw bad("'" + tok[i] + "' is not a finite number");
			v.push_back(*x);
		}
		const auto id = number(tok[0]);
		if (!id || *id != std::floor(*id) || std::abs(*id) > 9.0e15)
			throw bad("'" + tok[0] + "' is not a landmark ID");
		if (kind)
		{
			if (v.size() < 3) throw bad("expected 'id kind x y phi [covariance]'");
			l.kind = *kind;
		}
		else if (v.size() == 2 || v.size() == 3)
			l.kind = v.size() == 2 ? LandmarkKind::Point : LandmarkKind::Pose;
		else
			throw bad("expected 'id kind x y phi ...', 'id x y' or 'id x y phi'");
		const bool point = l.kind == LandmarkKind::Point;
		l.mean << v[0], v[1], point || v.size() < 3 ? 0.0 : v[2];
		if (kind && v.size() >= 9)
		{
			l.cov << v[3], v[4], v[5], v[4], v[6], v[7], v[5], v[7], v[8];
			if (point) l.cov.row(2).setZero(), l.cov.col(2).setZero();
			const int n = point ? 2 : 3;
			if (Eigen::LLT<Eigen::MatrixXd>(l.cov.topLeftCorner(n, n)).info() != Eigen::Success)
				throw bad("the covariance is not positive definite");
		}
		else
			l.cov = Eigen::Vector3d(stdXY * stdXY, stdXY * stdXY, point ? 0.0 : stdPhi * stdPhi)
						.asDiagonal();
		const LandmarkKey key{l.kind, static_cast<int64_t>(*id)};
		if (!seen.insert(key).second)
			throw bad("landmark " + tok[0] + " appears twice");
		map.push_back({key, l});
		if (measurements)
			measurements->push_back(kind && v.size() >= 10 && v[9] >= 0 && v[9] < 1e15 ? uint64_t(v[9]) : 0);
	}
	return map;
}

void writeLandmarkMap(const std::string& file, const LandmarkMap& map,
	const std::vector<uint64_t>& measurements, const std::string& runId)
{
	COutputFile out(file, COutputFile::Mode::Atomic);
	out.print("%% id kind x y phi var_x cov_xy cov_xphi var_y cov_yphi var_phi measurements\n");
	if (!runId.empty()) out.print("%% vslam run %s\n", runId.c_str());
	for (size_t row = 0; row < map.size(); row++)
	{
		const auto& [key, l] = map[row];
		const auto& C = l.cov;
		out.print("%lld %s %.6f %.6f %.6f %.9g %.9g %.9g %.9g %.9g %.9g %llu\n",
			static_cast<long long>(key.id), toString(key.kind), l.mean[0], l.mean[1],
			l.mean[2], C(0, 0), C(0, 1), C(0, 2), C(1, 1), C(1, 2), C(2, 2),
			static_cast<unsigned long long>(row < measurements.size() ? measurements[row] : 0));
	}
	out.commit();
}
}  // namespace vslam

#include <libvslam/core/InputError.h>
#include <libvslam/io/COutputFile.h>
#include <libvslam/io/NumericTable.h>
#include <libvslam/io/Trajectory.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vslam
{
namespace
{
void sortByTime(Trajectory& t)
{
	std::stable_sort(t.begin(), t.end(), [](const auto& a, const auto& b) { return a.t < b.t; });
}
}  // namespace

Trajectory readTumTrajectory(const std::string& file)
{
	Trajectory out;
	for (const auto& r : readNumericTable(file, "#%"))
	{
		if (r.size() != 8)
			throw InputError("'" + file + "' is not a TUM trajectory (8 columns expected)");
		// Yaw of the quaternion (qx, qy, qz, qw) = (r4..r7).
		const double yaw = std::atan2(
			2 * (r[7] * r[6] + r[4] * r[5]), 1 - 2 * (r[5] * r[5] + r[6] * r[6]));
		out.push_back({r[0], {r[1], r[2], yaw}});
	}
	sortByTime(out);
	return out;
}

Trajectory readRbpfSlamPath(const std::string& file)
{
	Trajectory out;
	for (const auto& r : readNumericTable(file, "#%"))
	{
		if (r.size() != 8)
			throw InputError(
				"'" + file + "' is not an rbpf-slam path (8 columns: step x y z yaw pitch roll t)");
		out.push_back({r[7], {r[1], r[2], r[4]}, static_cast<long>(r[0])});
	}
	sortByTime(out);
	return out;
}

Trajectory readMrptStepPath(const std::string& file)
{
	Trajectory out;
	for (const auto& r : readNumericTable(file, "#%"))
	{
		if (r.size() != 6)
			throw InputError("'" + file +
				"' is not an MRPT pose list (6 columns: x y z yaw pitch roll)");
		out.push_back({std::nan(""), {r[0], r[1], r[3]}, static_cast<long>(out.size())});
	}
	return out;
}

Trajectory readTrajectory(const std::string& file)
{
	// Both formats have 8 columns: rbpf-slam's first column is an integer
	// step counter and its last a timestamp; TUM's first is a timestamp.
	const auto rows = readNumericTable(file, "#%");
	if (rows.empty()) return {};
	if (rows.front().size() == 6) return readMrptStepPath(file);
	const bool rbpf = std::all_of(rows.begin(), rows.end(), [](const auto& r) {
		return r.size() == 8 && r[0] == std::floor(r[0]) && r[0] >= 0 && r[0] < 1e8;
	});
	return rbpf ? readRbpfSlamPath(file) : readTumTrajectory(file);
}

void writeTumTrajectory(const std::string& file, const Trajectory& trajectory, const std::string& runId)
{
	COutputFile out(file, COutputFile::Mode::Atomic);
	out.print("# timestamp x y z qx qy qz qw\n");
	if (!runId.empty()) out.print("# vslam run %s\n", runId.c_str());
	for (const auto& p : trajectory)
	{
		double q[4];
		yawToQuaternion(p.pose.phi, q);
		out.print("%.6f %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n", p.t, p.pose.x, p.pose.y, 0.0, q[0], q[1], q[2], q[3]);
	}
	out.commit();
}

std::optional<se2::Pose> interpolate(const Trajectory& tr, double t, double maxGap)
{
	if (tr.empty() || t < tr.front().t || t > tr.back().t) return std::nullopt;
	const auto it = std::lower_bound(
		tr.begin(), tr.end(), t, [](const TimedPose& p, double v) { return p.t < v; });
	if (it->t == t) return it->pose;
	const auto& b = *it;
	const auto& a = *(it - 1);
	if (b.t - a.t > maxGap) return std::nullopt;
	const double s = (t - a.t) / (b.t - a.t);
	return se2::Pose{a.pose.x + s * (b.pose.x - a.pose.x),
					 a.pose.y + s * (b.pose.y - a.pose.y),
					 se2::wrap(a.pose.phi + s * se2::wrap(b.pose.phi - a.pose.phi))};
}

Trajectory timeWindow(const Trajectory& trajectory, double t0, double from, double to)
{
	const bool everything = from <= 0 && std::isinf(to) && to > 0;
	Trajectory out;
	for (const auto& p : trajectory)
		if (everything || (p.t - t0 >= from && p.t - t0 < to)) out.push_back(p);
	return out;
}
}  // namespace vslam

#pragma once
/** \file Trajectory.h
 * A timestamped planar trajectory and the file formats users compare:
 * TUM ("timestamp x y z qx qy qz qw", Sturm et al. 2012), rbpf-slam's
 * log_estimated_path.txt ("step x y z yaw pitch roll timestamp") and the
 * per-step pose lists MRPT's simulators write as ground truth
 * ("x y z yaw pitch roll", one row per rawlog step, no timestamps). */
#include <libvslam/models/SE2.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace vslam
{
struct TimedPose
{
	double t = 0;  //!< UNIX seconds (NaN: unknown)
	se2::Pose pose;
	long step = -1;  //!< rawlog step, if the format records it (-1: unknown)
};

using Trajectory = std::vector<TimedPose>;

/** Reads a TUM trajectory (lines starting with '#' are comments). Throws
 * InputError naming the file and line on malformed input. */
Trajectory readTumTrajectory(const std::string& file);
/** Reads rbpf-slam's log_estimated_path.txt ('%' comments). */
Trajectory readRbpfSlamPath(const std::string& file);
/** Reads an MRPT per-step pose list ("x y z yaw pitch roll", '%'
 * comments): row i is step i; timestamps unknown. */
Trajectory readMrptStepPath(const std::string& file);
/** Reads any of the three formats, told apart by their columns. */
Trajectory readTrajectory(const std::string& file);

void writeTumTrajectory(const std::string& file, const Trajectory& trajectory, const std::string& runId = "");

/** The pose at time t, linearly interpolated (shortest-arc heading);
 * nullopt outside the trajectory or across a gap longer than maxGap s. */
std::optional<se2::Pose> interpolate(
	const Trajectory& sortedByTime, double t, double maxGap);

/** The poses whose time is in [t0 + from, t0 + to) (evo's --t_start /
 * --t_end, relative): the part of a run to score on its own, e.g. the
 * exploration before the path comes back, or what follows it. Poses
 * without a time are kept only by the full window (from <= 0, to infinite). */
Trajectory timeWindow(const Trajectory& trajectory, double t0, double from, double to);

/** Quaternion (qx, qy, qz, qw) of a rotation about z. */
inline void yawToQuaternion(double yaw, double q[4])
{
	q[0] = 0;
	q[1] = 0;
	q[2] = std::sin(yaw / 2);
	q[3] = std::cos(yaw / 2);
}
}  // namespace vslam

#include <libvslam/app/CVSlamApp.h>
#include <libvslam/config/StrictRead.h>

using namespace vslam;
using namespace vslam::config;

void CVSlamApp::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	rawlog_file = readString(c, s, "rawlog_file", rawlog_file);
	output_dir = readString(c, s, "output_dir", output_dir);
	RANDOM_SEED = readInt(c, s, "RANDOM_SEED", RANDOM_SEED, Range::closed(-1, 4294967295.0));
	ground_truth_file = readString(c, s, "ground_truth_file", ground_truth_file);
	prior_map_file = readString(c, s, "prior_map_file", prior_map_file);
	localization_only = readBool(c, s, "localization_only", localization_only);
	initial_pose_unknown = readBool(c, s, "initial_pose_unknown", initial_pose_unknown);
	prior_map_std_xy =
		readDouble(c, s, "prior_map_std_xy", prior_map_std_xy, Range{0, 100, false, true});
	prior_map_std_phi = readDegreesAsRadians(
		c, s, "prior_map_std_phi_deg", prior_map_std_phi, Range{0, 360, false, true});
	initial_pose_from_ground_truth =
		readBool(c, s, "initial_pose_from_ground_truth", initial_pose_from_ground_truth);
	max_steps = static_cast<uint64_t>(readInt(c, s, "max_steps", 0, Range::closed(0, 1e15)));
	show_progress = readBool(c, s, "show_progress", show_progress);
}

void CVSlamApp::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "rawlog_file", rawlog_file, 25, 12,
		"Input rawlog (either MRPT format, .gz or plain); relative to this INI");
	c.write(s, "output_dir", output_dir, 25, 12,
		"Output folder (relative to the working folder); created if needed");
	c.write(s, "RANDOM_SEED", static_cast<long long>(RANDOM_SEED), 25, 12,
		"Seed of the random generator (-1: from the clock); same seed, same outputs");
	c.write(s, "ground_truth_file", ground_truth_file, 25, 12,
		"Optional ground truth (TUM, rbpf-slam path, or MRPT per-step pose list) for error figures");
	c.write(s, "prior_map_file", prior_map_file, 25, 12,
		"Optional map to start from (a final_map.vslam or final_map.txt of an earlier run, or rows 'id x y' / "
		"'id x y phi'); relative to this INI");
	c.write(s, "localization_only", localization_only, 25, 12,
		"Keep the prior map fixed (localize in it): no landmark is added, updated or removed");
	c.write(s, "initial_pose_unknown", initial_pose_unknown, 25, 12,
		"The start pose is unknown: find it in the prior map from the first recognitions of its landmarks");
	c.write(s, "prior_map_std_xy", prior_map_std_xy, 25, 12,
		"Position uncertainty of prior-map rows without covariance [m]");
	c.write(s, "prior_map_std_phi_deg", prior_map_std_phi * 180 / M_PI, 25, 12,
		"Heading uncertainty of prior-map rows without covariance [deg]");
	c.write(s, "initial_pose_from_ground_truth", initial_pose_from_ground_truth, 25, 12,
		"Start at the ground-truth pose of the first step instead of the initial_* keys");
	c.write(s, "max_steps", static_cast<long long>(max_steps), 25, 12,
		"Process at most this many rawlog steps (0: all)");
	c.write(s, "show_progress", show_progress, 25, 12, "Print a progress line");
}

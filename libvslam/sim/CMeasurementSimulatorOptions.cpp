#include <libvslam/config/ConfigError.h>
#include <libvslam/config/KeyValidation.h>
#include <libvslam/config/StrictRead.h>
#include <libvslam/sim/CMeasurementSimulator.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <sstream>

using namespace vslam;
using namespace vslam::config;


void CMeasurementSimulator::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	seed = static_cast<uint32_t>(readInt(c, s, "seed", seed, Range::closed(0, 4294967295.0)));
	mapping_duration = readDouble(c, s, "mapping_duration", mapping_duration, Range::nonNegative());
	duration = readDouble(c, s, "duration", duration, Range::positive());
	dt = readDouble(c, s, "dt", dt, Range::positive());
	speed = readDouble(c, s, "speed", speed, Range::positive());
	max_turn_rate = readDouble(c, s, "max_turn_rate", max_turn_rate, Range::positive());
	room_width = readDouble(c, s, "room_width", room_width, Range::positive());
	room_height = readDouble(c, s, "room_height", room_height, Range::positive());
	path_type = static_cast<PathType>(readChoice(
		c, s, "path_type", static_cast<size_t>(path_type), {"waypoints", "random"}));
	waypoints = readNumberList(c, s, "waypoints", waypoints);
	if (waypoints.size() % 2 != 0)
		throw ConfigError("[" + s + "] waypoints: expected x y pairs");
	if (path_type == PathType::Waypoints && waypoints.size() < 4)
		throw ConfigError("[" + s + "] waypoints: path_type=waypoints needs at least two points");
	for (size_t i = 0; i < waypoints.size(); i += 2)
		if (waypoints[i] < 0 || waypoints[i] > room_width || waypoints[i + 1] < 0 ||
			waypoints[i + 1] > room_height)
			throw ConfigError("[" + s + "] waypoints: point " + std::to_string(i / 2 + 1) +
				" lies outside the room (walls are impassable)");
	wall_margin = readDouble(c, s, "wall_margin", wall_margin, Range::nonNegative());
	if (2 * wall_margin >= std::min(room_width, room_height))
		throw ConfigError("[" + s + "] wall_margin leaves no free space in the room");

	odo_sigma_T = readDouble(c, s, "odo_sigma_T", odo_sigma_T, Range::closed(0, 10));
	odo_sigma_R = readDouble(c, s, "odo_sigma_R", odo_sigma_R, Range::closed(0, 10));
	odo_sigma_R_per_meter = readDouble(c, s, "odo_sigma_R_per_meter", odo_sigma_R_per_meter, Range::closed(0, 10));
	odo_scale_bias = readDouble(c, s, "odo_scale_bias", odo_scale_bias, Range::closed(-0.5, 0.5));
	odo_turn_bias = readDouble(c, s, "odo_turn_bias", odo_turn_bias, Range::closed(-0.5, 0.5));
	slip_probability = readDouble(c, s, "slip_probability", slip_probability, Range::closed(0, 1));
	slip_std = readDouble(c, s, "slip_std", slip_std, Range::closed(0, 10));

	landmark_type = static_cast<LandmarkType>(readChoice(
		c, s, "landmark_type", static_cast<size_t>(landmark_type), {"visual", "range_bearing"}));
	camera_rate = readDouble(c, s, "camera_rate", camera_rate, Range::positive());
	camera_fov = readDegreesAsRadians(c, s, "camera_fov_deg", camera_fov, {0, 180, false, true});
	scene_depth_min = readDouble(c, s, "scene_depth_min", scene_depth_min, Range::positive());
	scene_depth_max = readDouble(c, s, "scene_depth_max", scene_depth_max, Range::positive());
	if (scene_depth_max < scene_depth_min)
		throw ConfigError("[" + s + "] scene_depth_max must be >= scene_depth_min");
	max_view_change = readDegreesAsRadians(c, s, "max_view_change_deg", max_view_change, Range::closed(0, 180));
	max_scale_change = readDouble(c, s, "max_scale_change", max_scale_change, Range::closed(1, 100));
	recognition_probability = readDouble(c, s, "recognition_probability", recognition_probability, Range::closed(0, 1));
	creation_min_distance = readDouble(c, s, "creation_min_distance", creation_min_distance, Range::nonNegative());
	creation_min_angle = readDegreesAsRadians(c, s, "creation_min_angle_deg", creation_min_angle, Range::closed(0, 180));
	meas_std_dx = readDouble(c, s, "meas_std_dx", meas_std_dx, Range::closed(0, 100));
	meas_std_dy = readDouble(c, s, "meas_std_dy", meas_std_dy, Range::closed(0, 100));
	meas_std_dphi = readDegreesAsRadians(c, s, "meas_std_dphi_deg", meas_std_dphi, Range::closed(0, 360));
	landmark_frame_std_xy = readDouble(c, s, "landmark_frame_std_xy", landmark_frame_std_xy, Range::closed(0, 100));
	landmark_frame_std_phi = readDegreesAsRadians(c, s, "landmark_frame_std_phi_deg", landmark_frame_std_phi, Range::closed(0, 360));
	bad_measurement_probability = readDouble(c, s, "bad_measurement_probability", bad_measurement_probability, Range::closed(0, 1));
	false_recognition_probability = readDouble(c, s, "false_recognition_probability", false_recognition_probability, Range::closed(0, 1));

	point_landmarks = static_cast<uint32_t>(readInt(c, s, "point_landmarks", point_landmarks, Range::closed(0, 1e6)));
	rb_max_range = readDouble(c, s, "rb_max_range", rb_max_range, Range::positive());
	rb_fov = readDegreesAsRadians(c, s, "rb_fov_deg", rb_fov, {0, 360, false, true});
	rb_std_range = readDouble(c, s, "rb_std_range", rb_std_range, Range{0, 1000, false, true});
	rb_std_bearing = readDegreesAsRadians(c, s, "rb_std_bearing_deg", rb_std_bearing, Range{0, 360, false, true});

	kidnap_times = readNumberList(c, s, "kidnap_times", kidnap_times);
	for (double t : kidnap_times)
		if (t < 0 || t > duration)
			throw ConfigError("[" + s + "] kidnap_times: " + std::to_string(t) + " is outside [0, duration]");
	kidnap_min_distance = readDouble(c, s, "kidnap_min_distance", kidnap_min_distance, Range::nonNegative());
}

void CMeasurementSimulator::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	const auto deg = [](double r) { return r * 180 / M_PI; };
	c.write(s, "seed", static_cast<int>(seed), 30, 10, "Random seed (same seed, same rawlog)");
	c.write(s, "mapping_duration", mapping_duration, 30, 10, "Unrecorded driving first, building the front-end's landmarks [s]");
	c.write(s, "duration", duration, 30, 10, "Recorded time [s]");
	c.write(s, "dt", dt, 30, 10, "Odometry period [s] (one rawlog entry each)");
	c.write(s, "speed", speed, 30, 10, "Forward speed [m/s]");
	c.write(s, "max_turn_rate", max_turn_rate, 30, 10, "Turn rate limit [rad/s]");
	c.write(s, "room_width", room_width, 30, 10, "Room size along x [m]");
	c.write(s, "room_height", room_height, 30, 10, "Room size along y [m]");
	c.write(s, "path_type", std::string(path_type == PathType::Waypoints ? "waypoints" : "random"), 30, 10, "waypoints | random");
	c.write(s, "waypoints", joinNumbers(waypoints), 30, 10, "x1 y1 x2 y2 ... visited cyclically");
	c.write(s, "wall_margin", wall_margin, 30, 10, "Random goals keep this distance to walls [m]");
	c.write(s, "odo_sigma_T", odo_sigma_T, 30, 10, "Odometry translational noise [m/sqrt(m)]");
	c.write(s, "odo_sigma_R", odo_sigma_R, 30, 10, "Odometry rotational noise [rad/sqrt(rad)]");
	c.write(s, "odo_sigma_R_per_meter", odo_sigma_R_per_meter, 30, 10, "Odometry heading drift [rad/sqrt(m)]");
	c.write(s, "odo_scale_bias", odo_scale_bias, 30, 10, "Systematic relative distance error");
	c.write(s, "odo_turn_bias", odo_turn_bias, 30, 10, "Systematic relative rotation error (wheelbase)");
	c.write(s, "slip_probability", slip_probability, 30, 10, "Wheel slip probability per odometry period");
	c.write(s, "slip_std", slip_std, 30, 10, "Position error of one slip [m]");
	c.write(s, "landmark_type", std::string(landmark_type == LandmarkType::Visual ? "visual" : "range_bearing"), 30, 10, "visual | range_bearing");
	c.write(s, "camera_rate", camera_rate, 30, 10, "Frames per second");
	c.write(s, "camera_fov_deg", deg(camera_fov), 30, 10, "Camera horizontal field of view [deg]");
	c.write(s, "scene_depth_min", scene_depth_min, 30, 10, "Depth of a landmark's scene ahead of the camera, min [m]");
	c.write(s, "scene_depth_max", scene_depth_max, 30, 10, "... max [m]");
	c.write(s, "max_view_change_deg", deg(max_view_change), 30, 10, "Recognized from directions within this angle of the original [deg]");
	c.write(s, "max_scale_change", max_scale_change, 30, 10, "... and distances within this factor of the original");
	c.write(s, "recognition_probability", recognition_probability, 30, 10, "Probability a visible landmark is recognized");
	c.write(s, "creation_min_distance", creation_min_distance, 30, 10, "New landmark only this far from all others [m]");
	c.write(s, "creation_min_angle_deg", deg(creation_min_angle), 30, 10, "... or with this heading difference [deg]");
	c.write(s, "meas_std_dx", meas_std_dx, 30, 10, "Visual measurement noise dx [m]");
	c.write(s, "meas_std_dy", meas_std_dy, 30, 10, "Visual measurement noise dy [m]");
	c.write(s, "meas_std_dphi_deg", deg(meas_std_dphi), 30, 10, "Visual measurement noise dtheta [deg]");
	c.write(s, "landmark_frame_std_xy", landmark_frame_std_xy, 30, 10, "Per-landmark frame reconstruction error [m]");
	c.write(s, "landmark_frame_std_phi_deg", deg(landmark_frame_std_phi), 30, 10, "Per-landmark frame heading error [deg]");
	c.write(s, "bad_measurement_probability", bad_measurement_probability, 30, 10, "Share of measurements with bad statistics");
	c.write(s, "false_recognition_probability", false_recognition_probability, 30, 10, "Share of false recognitions passing the pre-filter");
	c.write(s, "point_landmarks", static_cast<int>(point_landmarks), 30, 10, "Range-bearing: number of point landmarks");
	c.write(s, "rb_max_range", rb_max_range, 30, 10, "Range-bearing: max range [m]");
	c.write(s, "rb_fov_deg", deg(rb_fov), 30, 10, "Range-bearing: field of view [deg]");
	c.write(s, "rb_std_range", rb_std_range, 30, 10, "Range-bearing: range noise [m]");
	c.write(s, "rb_std_bearing_deg", deg(rb_std_bearing), 30, 10, "Range-bearing: bearing noise [deg]");
	c.write(s, "kidnap_times", joinNumbers(kidnap_times), 30, 10, "Times [s] at which the robot is kidnapped");
	c.write(s, "kidnap_min_distance", kidnap_min_distance, 30, 10, "Kidnap displacement at least [m]");
}

vslam::CMeasurementSimulator::TOptions vslam::loadMeasurementSimOptions(
	const std::string& iniText, const std::vector<config::Override>& overrides)
{
	const mrpt::config::CConfigFileMemory cfg = config::parseIniWithOverrides(iniText, overrides);
	CMeasurementSimulator::TOptions options;
	config::KnownKeys known;
	known.addFromOptions(options, CMeasurementSimulator::TOptions::kSection);
	config::checkNoUnknownKeys(cfg, known, CMeasurementSimulator::TOptions::kSection);
	options.loadFromConfigFile(cfg, CMeasurementSimulator::TOptions::kSection);
	return options;
}

#include <libvslam/config/ConfigError.h>
#include <libvslam/config/KeyValidation.h>
#include <libvslam/config/StrictRead.h>
#include <libvslam/sim/CVisualSimulator.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cmath>
#include <filesystem>

namespace vslam
{
using namespace vslam::config;

namespace
{
std::vector<double> readList(
	const mrpt::config::CConfigFileBase& c, const std::string& s, const std::string& key,
	const std::vector<double>& def, size_t groupSize, const char* groupSyntax)
{
	std::vector<double> v = readNumberList(c, s, key, def);
	if (v.size() % groupSize != 0)
		throw ConfigError("[" + s + "] " + key + ": expected groups of " + groupSyntax);
	return v;
}

void checkTimes(const std::string& s, const std::string& key, const std::vector<double>& v, size_t stride,
	double duration)
{
	for (size_t i = 0; i < v.size(); i += stride)
		if (v[i] < 0 || v[i] > duration)
			throw ConfigError("[" + s + "] " + key + ": time " + std::to_string(v[i]) + " is outside [0, duration]");
}

void checkIntervals(const std::string& s, const std::string& key, const std::vector<double>& v, double duration)
{
	if (v.size() % 2) throw ConfigError("[" + s + "] " + key + ": expected pairs 't0 t1'");
	checkTimes(s, key, v, 1, duration);
	for (size_t i = 0; i < v.size(); i += 2)
		if (v[i + 1] <= v[i]) throw ConfigError("[" + s + "] " + key + ": interval end before its start");
}
}  // namespace

CVisualSimulator::TOptions::TOptions()
{
	camera.ncols = 320;
	camera.nrows = 240;
	camera.setIntrinsicParamsFromValues(250, 250, 159.5, 119.5);
	camera.dist.fill(0);
}

mrpt::poses::CPose3D CVisualSimulator::TOptions::cameraPoseOnRobot() const
{
	const double d = M_PI / 180;
	// The mount's yaw/pitch/roll turn a forward-looking camera; the fixed
	// rotation maps robot axes (x ahead, z up) to camera axes (z ahead, y down).
	return mrpt::poses::CPose3D(
			   camera_mount[0], camera_mount[1], camera_mount[2], camera_mount[3] * d, camera_mount[4] * d,
			   camera_mount[5] * d) +
		mrpt::poses::CPose3D(0, 0, 0, -M_PI / 2, 0, -M_PI / 2);
}

size_t CVisualSimulator::TOptions::stepsPerFrame() const
{
	return std::max<size_t>(1, static_cast<size_t>(std::lround(1.0 / (camera_rate * dt))));
}

void CVisualSimulator::TOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	seed = static_cast<uint32_t>(readInt(c, s, "seed", seed, Range::closed(0, 4294967295.0)));
	world_file = readString(c, s, "world_file", world_file);
	world_seed = static_cast<uint32_t>(readInt(c, s, "world_seed", world_seed, Range::closed(0, 4294967295.0)));
	if (world_file.empty() == (world_seed == 0))
		throw ConfigError("[" + s + "] world_file, world_seed: give either a world file or a generated home's seed (world_seed = 0 uses the world file)");
	texture_dir = readString(c, s, "texture_dir", texture_dir);
	texture_max_side = static_cast<int>(readInt(c, s, "texture_max_side", texture_max_side, Range::closed(16, 16384)));
	duration = readDouble(c, s, "duration", duration, Range::closed(0, 1e6));
	if (duration <= 0) throw ConfigError("[" + s + "] duration must be positive");
	dt = readDouble(c, s, "dt", dt, {0.001, 10, true, true});

	speed = readDouble(c, s, "speed", speed, {0, 5, false, true});
	max_turn_rate = readDouble(c, s, "max_turn_rate", max_turn_rate, {0, 10, false, true});
	robot_radius = readDouble(c, s, "robot_radius", robot_radius, {0, 2, false, true});
	path_type = static_cast<PathType>(
		readChoice(c, s, "path_type", static_cast<size_t>(path_type), {"waypoints", "random", "tour", "roam"}));
	waypoints = readList(c, s, "waypoints", waypoints, 2, "'x y'");
	if (path_type == PathType::Waypoints && waypoints.size() < 4)
		throw ConfigError("[" + s + "] waypoints: path_type=waypoints needs at least two points");
	start_pose = readList(c, s, "start_pose", start_pose, 3, "'x y phi_deg'");
	if (start_pose.size() != 3) throw ConfigError("[" + s + "] start_pose: expected 'x y phi_deg'");
	laps = static_cast<int>(readInt(c, s, "laps", laps, Range::closed(0, 1000)));

	odometry.sigma_T = readDouble(c, s, "odo_sigma_T", odometry.sigma_T, Range::closed(0, 10));
	odometry.sigma_R = readDouble(c, s, "odo_sigma_R", odometry.sigma_R, Range::closed(0, 10));
	odometry.sigma_R_per_meter = readDouble(c, s, "odo_sigma_R_per_meter", odometry.sigma_R_per_meter, Range::closed(0, 10));
	odometry.scale_bias = readDouble(c, s, "odo_scale_bias", odometry.scale_bias, Range::closed(-0.5, 0.5));
	odometry.turn_bias = readDouble(c, s, "odo_turn_bias", odometry.turn_bias, Range::closed(-0.5, 0.5));
	odometry.slip_probability = readDouble(c, s, "slip_probability", odometry.slip_probability, Range::closed(0, 1));
	odometry.slip_std = readDouble(c, s, "slip_std", odometry.slip_std, Range::closed(0, 10));

	loadCamera(c, s);

	laser_rays = static_cast<int>(readInt(c, s, "laser_rays", laser_rays, Range::closed(2, 10000)));
	laser_fov = readDegreesAsRadians(c, s, "laser_fov_deg", laser_fov, {0, 360, false, true});
	laser_max_range = readDouble(c, s, "laser_max_range", laser_max_range, {0, 1000, false, true});
	laser_std = readDouble(c, s, "laser_std", laser_std, Range::closed(0, 10));
	laser_pose = readNumberList(c, s, "laser_pose", laser_pose);
	if (laser_pose.size() != 3) throw ConfigError("[" + s + "] laser_pose: expected 'x y z'");

	loadEvents(c, s);
}

void CVisualSimulator::TOptions::loadCamera(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	camera_rate = readDouble(c, s, "camera_rate", camera_rate, {0, 100, false, true});
	const double stepsPerFrame = 1.0 / (camera_rate * dt);
	if (stepsPerFrame < 1 - 1e-6 || std::abs(stepsPerFrame - std::round(stepsPerFrame)) > 1e-6)
		throw ConfigError("[" + s + "] camera_rate: one frame every whole number of steps is needed (1 / (camera_rate * dt) = " +
			std::to_string(stepsPerFrame) + ")");
	camera.ncols = static_cast<uint32_t>(readInt(c, s, "camera_ncols", camera.ncols, Range::closed(16, 4096)));
	camera.nrows = static_cast<uint32_t>(readInt(c, s, "camera_nrows", camera.nrows, Range::closed(16, 4096)));
	camera.fx(readDouble(c, s, "camera_fx", camera.fx(), {1, 1e5, true, true}));
	camera.fy(readDouble(c, s, "camera_fy", camera.fy(), {1, 1e5, true, true}));
	camera.cx(readDouble(c, s, "camera_cx", camera.cx(), Range::closed(0, camera.ncols)));
	camera.cy(readDouble(c, s, "camera_cy", camera.cy(), Range::closed(0, camera.nrows)));
	std::vector<double> dist(camera.dist.begin(), camera.dist.begin() + 5);
	dist = readNumberList(c, s, "camera_dist", dist);
	if (dist.size() != 5) throw ConfigError("[" + s + "] camera_dist: expected 'k1 k2 p1 p2 k3'");
	for (double v : dist)
		if (std::abs(v) > 10) throw ConfigError("[" + s + "] camera_dist: coefficient above 10 in magnitude");
	camera.dist.fill(0);
	for (size_t i = 0; i < 5; i++) camera.dist[i] = dist[i];
	camera_mount = readNumberList(c, s, "camera_mount", camera_mount);
	if (camera_mount.size() != 6) throw ConfigError("[" + s + "] camera_mount: expected 'x y z yaw pitch roll'");
	camera_grayscale = readBool(c, s, "camera_grayscale", camera_grayscale);
	imaging.auto_exposure = readBool(c, s, "camera_auto_exposure", imaging.auto_exposure);
	imaging.max_exposure_time = readDouble(c, s, "exposure_time", imaging.max_exposure_time, {0, 1, false, true});
	imaging.max_gain = readDouble(c, s, "camera_max_gain", imaging.max_gain, Range::closed(1, 64));
	imaging.ae_time_constant = readDouble(c, s, "camera_ae_time_constant", imaging.ae_time_constant, Range::closed(0, 60));
	imaging.vignetting = readDouble(c, s, "camera_vignetting", imaging.vignetting, Range::closed(0, 0.9));
	imaging.white_balance_error =
		readDouble(c, s, "camera_white_balance_error", imaging.white_balance_error, Range::closed(0, 0.5));
	imaging.full_well = readDouble(c, s, "camera_full_well", imaging.full_well, {1, 1e7, true, true});
	imaging.read_noise = readDouble(c, s, "camera_read_noise", imaging.read_noise, Range::closed(0, 1e4));
	camera_bump_rate = readDouble(c, s, "camera_bump_rate", camera_bump_rate, Range::closed(0, 10));
	camera_jitter_deg = readDouble(c, s, "camera_jitter_deg", camera_jitter_deg, Range::closed(0, 10));
	image_format = readWord(c, s, "image_format", image_format, {"png", "jpg"});
	jpeg_quality = static_cast<int>(readInt(c, s, "jpeg_quality", jpeg_quality, Range::closed(1, 100)));
}

void CVisualSimulator::TOptions::loadEvents(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	kidnap_times = readNumberList(c, s, "kidnap_times", kidnap_times);
	checkTimes(s, "kidnap_times", kidnap_times, 1, duration);
	kidnap_min_distance = readDouble(c, s, "kidnap_min_distance", kidnap_min_distance, Range::closed(0, 1000));
	kidnap_target = static_cast<KidnapTarget>(
		readChoice(c, s, "kidnap_target", static_cast<size_t>(kidnap_target), {"visited", "anywhere"}));
	light_changes = readList(c, s, "light_changes", light_changes, 2, "'t gain'");
	checkTimes(s, "light_changes", light_changes, 2, duration);
	for (size_t i = 1; i < light_changes.size(); i += 2)
		if (light_changes[i] < 0 || light_changes[i] > 10)
			throw ConfigError("[" + s + "] light_changes: gain outside [0, 10]");
	dark_spells = readNumberList(c, s, "dark_spells", dark_spells);
	checkIntervals(s, "dark_spells", dark_spells, duration);
	dark_gain = readDouble(c, s, "dark_gain", dark_gain, Range::closed(0, 1));
	blackouts = readNumberList(c, s, "blackouts", blackouts);
	checkIntervals(s, "blackouts", blackouts, duration);
	people = readList(c, s, "people", people, 6, "'t x0 y0 x1 y1 speed'");
	checkTimes(s, "people", people, 6, duration);
	for (size_t i = 5; i < people.size(); i += 6)
		if (people[i] <= 0 || people[i] > 5) throw ConfigError("[" + s + "] people: walking speed outside (0, 5] m/s");
	random_people = static_cast<int>(readInt(c, s, "random_people", random_people, Range::closed(0, 1000)));
}

void CVisualSimulator::TOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	const auto w = [&](const std::string& key, const auto& value, const std::string& comment) {
		c.write(s, key, value, 30, 10, comment);
	};
	w("seed", static_cast<int>(seed), "Random seed (same seed, same rawlog and images)");
	w("world_file", world_file, "World file (walls, furniture, pictures, doors); relative to this INI");
	w("world_seed", static_cast<long>(world_seed), "A generated home instead of world_file (0: none)");
	w("texture_dir", texture_dir, "Folder of the photographs the world file names");
	w("texture_max_side", texture_max_side, "Longest side of one surface's texture [px]");
	w("duration", duration, "Simulated time [s]");
	w("dt", dt, "Step period [s]: one rawlog entry (odometry + laser) per step");
	w("speed", speed, "Forward speed [m/s]");
	w("max_turn_rate", max_turn_rate, "Turn rate limit [rad/s]");
	w("robot_radius", robot_radius, "Robot radius, kept clear of obstacles [m]");
	static const char* kPaths[] = {"waypoints", "random", "tour", "roam"};
	w("path_type", std::string(kPaths[static_cast<size_t>(path_type)]),
		"waypoints (looped) | random (goals in sight) | tour (every room, looped) | roam (goals anywhere, planned)");
	w("waypoints", joinNumbers(waypoints), "x1 y1 x2 y2 ... [m], driven in a loop");
	w("start_pose", joinNumbers(start_pose), "x y phi_deg: start of a random, tour or roam path");
	w("laps", laps, "Waypoint and tour loops: stop after this many (0: at duration)");
	w("odo_sigma_T", odometry.sigma_T, "Odometry translational noise [m/sqrt(m)] (paper's sigma_T)");
	w("odo_sigma_R", odometry.sigma_R, "Odometry rotational noise [rad/sqrt(rad)] (paper's sigma_R)");
	w("odo_sigma_R_per_meter", odometry.sigma_R_per_meter, "Odometry heading drift [rad/sqrt(m)]");
	w("odo_scale_bias", odometry.scale_bias, "Systematic relative distance error");
	w("odo_turn_bias", odometry.turn_bias, "Systematic relative rotation error (wheelbase)");
	w("slip_probability", odometry.slip_probability, "Wheel slip probability per step");
	w("slip_std", odometry.slip_std, "Position error of one slip [m]");
	w("camera_rate", camera_rate, "Frames per second");
	w("camera_ncols", static_cast<int>(camera.ncols), "Image width [px]");
	w("camera_nrows", static_cast<int>(camera.nrows), "Image height [px]");
	w("camera_fx", camera.fx(), "Focal length x [px]");
	w("camera_fy", camera.fy(), "Focal length y [px]");
	w("camera_cx", camera.cx(), "Principal point x [px]");
	w("camera_cy", camera.cy(), "Principal point y [px]");
	w("camera_dist",
		joinNumbers({camera.dist[0], camera.dist[1], camera.dist[2], camera.dist[3], camera.dist[4]}),
		"Distortion k1 k2 p1 p2 k3 (MRPT / OpenCV model)");
	w("camera_mount", joinNumbers(camera_mount), "Camera on the robot: x y z [m] yaw pitch roll [deg], 0 0 0 looks ahead");
	w("camera_grayscale", camera_grayscale, "Grey images instead of colour");
	w("camera_auto_exposure", imaging.auto_exposure, "Exposure time and gain follow the scene's brightness");
	w("exposure_time", imaging.max_exposure_time, "Longest exposure [s] (motion blur; the shortest is 1/20 of it)");
	w("camera_max_gain", imaging.max_gain, "Analogue gain limit of the auto-exposure");
	w("camera_ae_time_constant", imaging.ae_time_constant, "Auto-exposure lag [s]");
	w("camera_vignetting", imaging.vignetting, "Light lost in the image corners (0-1)");
	w("camera_white_balance_error", imaging.white_balance_error, "Std of the white balance error per channel");
	w("camera_full_well", imaging.full_well, "Electrons at saturation at gain 1 (shot noise)");
	w("camera_read_noise", imaging.read_noise, "Read noise [electrons]");
	w("camera_bump_rate", camera_bump_rate, "Bumps per second (a jolt of pitch and vertical blur)");
	w("camera_jitter_deg", camera_jitter_deg, "Std of the camera's pitch and roll from the floor [deg]");
	w("image_format", image_format, "jpg | png (files in <rawlog>_Images/)");
	w("jpeg_quality", jpeg_quality, "JPEG quality (1-100)");
	w("laser_rays", laser_rays, "Laser rays per scan");
	w("laser_fov_deg", laser_fov * 180 / M_PI, "Laser field of view [deg]");
	w("laser_max_range", laser_max_range, "Laser maximum range [m]");
	w("laser_std", laser_std, "Laser range noise [m]");
	w("laser_pose", joinNumbers(laser_pose), "Laser on the robot: x y z [m]");
	w("kidnap_times", joinNumbers(kidnap_times), "Times [s] at which the robot is carried elsewhere");
	w("kidnap_min_distance", kidnap_min_distance, "Kidnap displacement at least [m]");
	w("kidnap_target", std::string(kidnap_target == KidnapTarget::Visited ? "visited" : "anywhere"),
		"visited (a pose the robot had before) | anywhere (a random free pose)");
	w("light_changes", joinNumbers(light_changes), "t gain ...: lighting times gain from t on");
	w("dark_spells", joinNumbers(dark_spells), "t0 t1 ...: dark spells (lighting at dark_gain)");
	w("dark_gain", dark_gain, "Lighting during a dark spell");
	w("blackouts", joinNumbers(blackouts), "t0 t1 ...: camera blackouts (black frames)");
	w("people", joinNumbers(people), "t x0 y0 x1 y1 speed ...: people walking through");
	w("random_people", random_people, "People walking between random free places at random times");
}

CVisualSimulator::TOptions loadVisualSimOptions(
	const std::string& iniText, const std::vector<config::Override>& overrides, const std::string& iniDirectory)
{
	const mrpt::config::CConfigFileMemory cfg = config::parseIniWithOverrides(iniText, overrides);
	CVisualSimulator::TOptions options;
	config::KnownKeys known;
	known.addFromOptions(options, CVisualSimulator::TOptions::kSection);
	config::checkNoUnknownKeys(cfg, known, CVisualSimulator::TOptions::kSection);
	options.loadFromConfigFile(cfg, CVisualSimulator::TOptions::kSection);
	if (!options.world_file.empty() && std::filesystem::path(options.world_file).is_relative() && !iniDirectory.empty())
		options.world_file = (std::filesystem::path(iniDirectory) / options.world_file).string();
	return options;
}
}  // namespace vslam

#pragma once
/** \file TVisualSimOptions.h
 * Options of the rendered simulator vslam-simul (INI section
 * [vslam_simul]): the world file, the robot and its path, odometry errors,
 * the camera (calibration, mount, image defects), the laser, and the
 * scheduled events (kidnapping, lighting changes, dark spells, camera
 * blackouts, people walking through). Every key is listed with its default
 * in config_ini/simul_example.ini.
 */
#include <libvslam/config/Overrides.h>
#include <libvslam/sim/CameraImaging.h>
#include <libvslam/sim/OdometryErrorModel.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/img/TCamera.h>
#include <mrpt/poses/CPose3D.h>

#include <cstdint>
#include <string>
#include <vector>

namespace vslam
{
struct TVisualSimOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "vslam_simul";

	/** waypoints: the listed loop; random: random goals in straight sight;
	 * tour: a systematic loop through every room (PathPlanner.h); roam:
	 * random goals anywhere in the home, reached by planned paths. */
	enum class PathType : uint8_t { Waypoints = 0, Random = 1, Tour = 2, Roam = 3 };
	enum class KidnapTarget : uint8_t { Visited = 0, Anywhere = 1 };

	uint32_t seed = 1;
	/** World file (FloorPlanFile.h); relative paths are relative to the INI. */
	std::string world_file;
	/** A generated home (HomeGenerator.h) instead of world_file, when not 0;
	 * the robot starts at the home's start. */
	uint32_t world_seed = 0;
	/** Folder of the photographs named in the world file. */
	std::string texture_dir = "/usr/share";
	int texture_max_side = 2048;  //!< px, longest side of one surface's texture
	double duration = 120;  //!< s
	double dt = 0.2;  //!< s, one rawlog entry (odometry + laser) per step

	// Robot and path
	double speed = 0.15;  //!< m/s (paper: about 15 cm/s)
	double max_turn_rate = 0.5;  //!< rad/s
	double robot_radius = 0.2;  //!< m, kept clear of every obstacle
	PathType path_type = PathType::Random;
	/** "x1 y1 x2 y2 ...": the path, driven in a loop (waypoints). The robot
	 * starts at the first point facing the second. */
	std::vector<double> waypoints;
	/** "x y phi_deg": start of a random, tour or roam path. */
	std::vector<double> start_pose{2, 1, 0};
	/** Waypoint and tour loops: stop after this many (0: at `duration`). */
	int laps = 0;

	TOdometryErrorModel odometry;

	// Camera
	double camera_rate = 2.5;  //!< frames per second; 1 / (camera_rate dt) a whole number
	mrpt::img::TCamera camera;  //!< calibration written into every image
	/** Camera on the robot: x y z (m) yaw pitch roll (deg); all angles 0
	 * looks straight ahead along the robot's x axis. */
	std::vector<double> camera_mount{0.1, 0, 0.3, 0, 0, 0};
	bool camera_grayscale = false;
	/** Exposure, vignetting, white balance, sensor noise; its
	 * max_exposure_time is the key exposure_time. */
	TCameraImagingOptions imaging;
	/** Bumps per second (floor joints, thresholds, rugs): a frame with a
	 * jolt of pitch and vertical blur. */
	double camera_bump_rate = 0.05;
	/** Standard deviation of the camera's pitch and roll from the floor's
	 * unevenness, per frame (deg). */
	double camera_jitter_deg = 0.15;
	std::string image_format = "jpg";  //!< png | jpg
	int jpeg_quality = 85;

	// Laser (for rbpf-slam)
	int laser_rays = 181;
	double laser_fov = M_PI;  //!< rad
	double laser_max_range = 8;  //!< m
	double laser_std = 0.01;  //!< m
	std::vector<double> laser_pose{0.15, 0, 0.2};  //!< x y z on the robot

	// Events
	std::vector<double> kidnap_times;  //!< s
	double kidnap_min_distance = 2.0;  //!< m
	/** visited: to a pose the robot had before (a place its map knows);
	 * anywhere: a random free pose. */
	KidnapTarget kidnap_target = KidnapTarget::Visited;
	/** "t1 gain1 t2 gain2 ...": from t on, the lighting is gain times the
	 * normal (1). */
	std::vector<double> light_changes;
	/** "t0 t1 ...": dark spells, lighting at dark_gain. */
	std::vector<double> dark_spells;
	double dark_gain = 0.06;
	/** "t0 t1 ...": the camera delivers black frames (lens covered). */
	std::vector<double> blackouts;
	/** "t x0 y0 x1 y1 speed ...": a person appears at (x0, y0) at time t
	 * and walks to (x1, y1) at speed m/s, then leaves. */
	std::vector<double> people;
	/** People walking between random free places at random times. */
	int random_people = 0;

	TVisualSimOptions();

	/** Camera mount as an MRPT camera pose on the robot (z forward). */
	mrpt::poses::CPose3D cameraPoseOnRobot() const;
	size_t stepsPerFrame() const;

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section) override;
	void saveToConfigFile(mrpt::config::CConfigFileBase& cfg, const std::string& section) const override;

   private:
	/** The camera keys: intrinsics, mount, imaging. */
	void loadCamera(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	/** The events: kidnaps, light changes, dark spells, blackouts, people. */
	void loadEvents(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
};

/** Options from INI text with --set overrides: unknown keys in
 * [vslam_simul] and bad values are ConfigErrors naming the key. A relative
 * world_file is resolved against iniDirectory. */
TVisualSimOptions loadVisualSimOptions(
	const std::string& iniText, const std::vector<config::Override>& overrides, const std::string& iniDirectory);
}  // namespace vslam

#pragma once
/** \file CVisualSimulator.h
 * The rendered simulator behind vslam-simul: a differential-drive robot
 * in a floor plan (scripted waypoint loop or collision-free random goals),
 * odometry with noise, biases and slips, a 2-D laser scan every step and a
 * rendered camera image every few steps, and the scheduled events. The
 * output is MRPT's action/sensory-frame form (for a rawlog that vslam and
 * rbpf-slam both read), the images written to a folder as they are
 * rendered, and the true and odometry paths. Deterministic for a seed: it
 * uses its own random generators, never the global one.
 */
#include <libvslam/config/Overrides.h>
#include <libvslam/io/RawlogWriting.h>
#include <libvslam/io/Trajectory.h>
#include <libvslam/sim/CameraImaging.h>
#include <libvslam/sim/OdometryErrorModel.h>
#include <libvslam/world/FloorPlan.h>
#include <libvslam/world/FreeSpace.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/img/TCamera.h>
#include <mrpt/poses/CPose3D.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace vslam
{
struct VisualSimRun
{
	std::vector<ActionFramePair> entries;
	Trajectory truePath;  //!< at every step
	Trajectory odometryPath;  //!< dead reckoning from the true start
	std::vector<size_t> kidnapSteps;
	size_t images = 0, blackFrames = 0, slips = 0;
	int laps = 0;  //!< loops completed (waypoints and tours)
	double renderSeconds = 0;  //!< wall time spent rendering images
};

class CVisualSimulator
{
   public:
	/** Options of the rendered simulator vslam-simul (INI section [vslam_simul]): the world file, the robot and its path, odometry errors, the camera (calibration, mount, image defects), the laser, and the scheduled events (kidnapping, lighting changes, dark spells, camera blackouts, people walking through). Every key is listed with its default in config_ini/simul_example.ini. */
	struct TOptions : public mrpt::config::CLoadableOptions
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

		TOptions();

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

	/** Checks the path against the floor plan: a start or waypoint that is
	 * not free, or a waypoint leg or person's walk through an obstacle, is
	 * an InputError naming the world file line of the obstacle. */
	CVisualSimulator(const CVisualSimulator::TOptions& options, const world::FloorPlan& plan);

	/** Simulates; images go to imagesDir (created) as "img_<step>.<ext>".
	 * progress(fraction) is called after every image. */
	VisualSimRun run(const std::string& imagesDir, const std::function<void(double)>& progress = {}) const;

	/** UNIX time of step 0. */
	static constexpr double kStartTime = 1700000000.0;

   private:
	CVisualSimulator::TOptions m_options;
	world::FloorPlan m_plan;
	world::FreeSpace m_free;  //!< where the robot can be, from its start
};

/** The floor's shake of a camera (camera axes: x right, y down, z ahead),
 * composed after its mount: a pitch about x and a roll about z, never a
 * turn about y (the camera is fixed to the robot, whose heading the
 * truth holds). */
mrpt::poses::CPose3D cameraShake(double pitchRad, double rollRad);

/** Floor plan, free space, true path (green), odometry path (red), kidnaps
 * (blue lines) as a PNG, 60 pixels per metre. */
void writeSimulationPreview(const world::FloorPlan& plan, const VisualSimRun& run, const std::string& pngFile);
/** Options from INI text with --set overrides: unknown keys in
 * [vslam_simul] and bad values are ConfigErrors naming the key. A relative
 * world_file is resolved against iniDirectory. */
CVisualSimulator::TOptions loadVisualSimOptions(
	const std::string& iniText, const std::vector<config::Override>& overrides, const std::string& iniDirectory);
}  // namespace vslam

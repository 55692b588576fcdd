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
#include <libvslam/io/RawlogWriting.h>
#include <libvslam/io/Trajectory.h>
#include <libvslam/sim/TVisualSimOptions.h>
#include <libvslam/world/FloorPlan.h>
#include <libvslam/world/FreeSpace.h>

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
	/** Checks the path against the floor plan: a start or waypoint that is
	 * not free, or a waypoint leg or person's walk through an obstacle, is
	 * an InputError naming the world file line of the obstacle. */
	CVisualSimulator(const TVisualSimOptions& options, const world::FloorPlan& plan);

	/** Simulates; images go to imagesDir (created) as "img_<step>.<ext>".
	 * progress(fraction) is called after every image. */
	VisualSimRun run(const std::string& imagesDir, const std::function<void(double)>& progress = {}) const;

	/** UNIX time of step 0. */
	static constexpr double kStartTime = 1700000000.0;

   private:
	TVisualSimOptions m_options;
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
}  // namespace vslam

#include <libvslam/core/InputError.h>
#include <libvslam/sim/CVisualSimulator.h>
#include <libvslam/sim/CameraRenderer.h>
#include <libvslam/sim/GoalDriver.h>
#include <libvslam/sim/SimulationEvents.h>
#include <libvslam/world/FreeSpace.h>
#include <libvslam/world/LaserRayCaster.h>
#include <libvslam/world/WorldScene.h>
#include <mrpt/img/CImage.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/system/CTicTac.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <filesystem>

namespace vslam
{
using world::FreeSpace;

namespace
{
Eigen::Vector2d waypoint(const TVisualSimOptions& o, size_t i)
{
	const size_t n = o.waypoints.size() / 2;
	return {o.waypoints[2 * (i % n)], o.waypoints[2 * (i % n) + 1]};
}

Eigen::Vector2d startPoint(const TVisualSimOptions& o)
{
	return o.path_type == TVisualSimOptions::PathType::Waypoints ? waypoint(o, 0)
																 : Eigen::Vector2d(o.start_pose[0], o.start_pose[1]);
}

std::string describe(const Eigen::Vector2d& p)
{
	char buf[64];
	std::snprintf(buf, sizeof(buf), "(%.2f, %.2f)", p[0], p[1]);
	return buf;
}

/** Random goals: a free cell in straight, collision-free sight. */
Eigen::Vector2d randomGoal(const FreeSpace& fs, const se2::Pose& from, mrpt::random::CRandomGenerator& rng)
{
	const Eigen::Vector2d p(from.x, from.y);
	for (int attempt = 0; attempt < 2000; attempt++)
	{
		const Eigen::Vector2d g = fs.freeCell(rng.drawUniform(0, 1));
		if ((g - p).norm() > 0.5 && fs.segmentIsFree(p, g)) return g;
	}
	throw InputError("no collision-free goal in sight of " + describe(p) + ": the free space is too cramped");
}

mrpt::obs::CObservation2DRangeScan::Ptr laserScan(const TVisualSimOptions& o, const std::vector<world::Segment>& segs,
	const std::vector<world::Circle>& people, const se2::Pose& robot, mrpt::random::CRandomGenerator& rng,
	mrpt::Clock::time_point t)
{
	auto scan = mrpt::obs::CObservation2DRangeScan::Create();
	scan->timestamp = t;
	scan->sensorLabel = "LASER";
	scan->aperture = static_cast<float>(o.laser_fov);
	scan->rightToLeft = true;
	scan->maxRange = static_cast<float>(o.laser_max_range);
	scan->stdError = static_cast<float>(o.laser_std);
	scan->sensorPose = mrpt::poses::CPose3D(o.laser_pose[0], o.laser_pose[1], o.laser_pose[2], 0, 0, 0);
	scan->resizeScan(static_cast<size_t>(o.laser_rays));
	const se2::Pose sensor = se2::compose(robot, {o.laser_pose[0], o.laser_pose[1], 0});
	const Eigen::Vector2d origin(sensor.x, sensor.y);
	for (int i = 0; i < o.laser_rays; i++)
	{
		const double a = sensor.phi - o.laser_fov / 2 + o.laser_fov * i / (o.laser_rays - 1);
		double r = world::castRay(segs, people, origin, {std::cos(a), std::sin(a)});
		r += o.laser_std * rng.drawGaussian1D_normalized();
		const bool valid = r > 0 && r < o.laser_max_range;
		scan->setScanRange(static_cast<size_t>(i), static_cast<float>(valid ? r : o.laser_max_range));
		scan->setScanRangeValidity(static_cast<size_t>(i), valid);
	}
	return scan;
}

/** Where a kidnapped robot is put: a random free pose at least
 * kidnap_min_distance away (waypoint loops: a random waypoint, heading for
 * the next one, whose index `nextWaypoint` becomes). */
se2::Pose kidnapTarget(const TVisualSimOptions& o, const FreeSpace& fs, const se2::Pose& from,
	mrpt::random::CRandomGenerator& rng, size_t& nextWaypoint)
{
	const bool waypoints = o.path_type == TVisualSimOptions::PathType::Waypoints;
	se2::Pose to;
	for (int attempt = 0; attempt < 1000; attempt++)
	{
		if (waypoints)
		{
			nextWaypoint = static_cast<size_t>(rng.drawUniform32bit() % (o.waypoints.size() / 2));
			const Eigen::Vector2d at = waypoint(o, nextWaypoint), next = waypoint(o, ++nextWaypoint);
			to = {at[0], at[1], std::atan2(next[1] - at[1], next[0] - at[0])};
		}
		else
		{
			const Eigen::Vector2d at = fs.freeCell(rng.drawUniform(0, 1));
			to = {at[0], at[1], rng.drawUniform(-M_PI, M_PI)};
		}
		if (std::hypot(to.x - from.x, to.y - from.y) >= o.kidnap_min_distance) break;
	}
	return to;
}

/** The camera image at step k: rendered, with the image defects of that
 * moment, written to imagesDir, as the observation that names it. */
mrpt::obs::CObservationImage::Ptr renderFrame(const TVisualSimOptions& o, const SimulationEvents& events,
	const world::WorldScene& world, CameraRenderer& renderer, const mrpt::poses::CPose3D& mount,
	const se2::Pose& robot, double turnRate, size_t k, mrpt::Clock::time_point t, const std::string& imagesDir)
{
	const double tRel = k * o.dt;
	cv::Mat img = renderer.render(world.scene(), mrpt::poses::CPose3D(mrpt::poses::CPose2D(robot)) + mount);
	CameraDefects d;
	d.gain = events.lightingGain(tRel);
	d.blackout = events.blackout(tRel);
	d.blurPixels = std::abs(turnRate) * o.exposure_time * o.camera.fx();
	d.noiseStd = o.image_noise_std;
	d.noiseSeed = (static_cast<uint64_t>(o.seed) << 32) ^ k;
	CameraRenderer::applyDefects(img, d);
	if (o.camera_grayscale) cv::cvtColor(img, img, cv::COLOR_BGR2GRAY);
	const std::string name = "img_" + std::to_string(k) + (o.image_format == "jpg" ? ".jpg" : ".png");
	if (!cv::imwrite(imagesDir + "/" + name, img)) throw InputError("cannot write image '" + imagesDir + "/" + name + "'");
	auto obs = mrpt::obs::CObservationImage::Create();
	obs->timestamp = t;
	obs->sensorLabel = "CAMERA";
	obs->cameraParams = o.camera;
	obs->cameraPose = mount;
	obs->image.setExternalStorage(name);
	return obs;
}
}  // namespace

CVisualSimulator::CVisualSimulator(const TVisualSimOptions& options, const world::FloorPlan& plan)
	: m_options(options), m_plan(plan), m_free(m_plan, options.robot_radius, startPoint(options))
{
	const TVisualSimOptions& o = m_options;
	const FreeSpace& fs = m_free;
	const auto blocked = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const std::string& what) {
		if (const world::Segment* s = fs.blockingSegment(a, b))
			throw InputError(
				what + " " + describe(a) + " -> " + describe(b) + " runs through (or within " +
				std::to_string(o.robot_radius) + " m of) the obstacle on line " + std::to_string(s->line) +
				" of world file '" + m_plan.sourceFile + "'");
		if (!fs.isFree(b)) throw InputError(what + " ends at " + describe(b) + ", which is not free space");
	};
	if (o.path_type == TVisualSimOptions::PathType::Waypoints)
	{
		const size_t n = o.waypoints.size() / 2;
		for (size_t i = 0; i < n; i++)
			blocked(waypoint(o, i), waypoint(o, i + 1),
				"[vslam_simul] waypoints: the leg from point " + std::to_string(i + 1));
	}
	SimulationEvents events(o);
	for (size_t i = 0; i < events.peopleCount(); i++)
	{
		const double* p = &o.people[6 * i];
		if (const world::Segment* s = fs.blockingSegment({p[1], p[2]}, {p[3], p[4]}))
			throw InputError("[vslam_simul] people: person " + std::to_string(i + 1) +
				" walks through the obstacle on line " + std::to_string(s->line) + " of world file '" +
				m_plan.sourceFile + "'");
	}
}

VisualSimRun CVisualSimulator::run(const std::string& imagesDir, const std::function<void(double)>& progress) const
{
	const TVisualSimOptions& o = m_options;
	std::filesystem::create_directories(imagesDir);
	mrpt::random::CRandomGenerator rng(o.seed);  // robot, odometry, laser, kidnaps
	const FreeSpace& fs = m_free;
	const SimulationEvents events(o);
	world::WorldScene world(m_plan, events.peopleCount(), o.texture_max_side);
	CameraRenderer renderer(o.camera);
	const mrpt::poses::CPose3D mount = o.cameraPoseOnRobot();
	const std::vector<world::Segment> segments = m_plan.obstacleSegments();

	DriveLimits limits;
	limits.speed = o.speed, limits.maxTurnRate = o.max_turn_rate, limits.dt = o.dt;
	limits.turnInPlaceAbove = 0.15;  // drive nearly straight legs: they were checked for collisions
	limits.goalTolerance = 0.05;
	size_t nextWaypoint = 1;
	const bool waypoints = o.path_type == TVisualSimOptions::PathType::Waypoints;
	GoalDriver driver(limits, [&](const se2::Pose& p) {
		return waypoints ? waypoint(o, ++nextWaypoint) : randomGoal(fs, p, rng);
	});
	se2::Pose pose;
	if (waypoints)
	{
		const Eigen::Vector2d a = waypoint(o, 0), b = waypoint(o, 1);
		pose = {a[0], a[1], std::atan2(b[1] - a[1], b[0] - a[0])};
		driver.setGoal(b);
	}
	else
	{
		pose = {o.start_pose[0], o.start_pose[1], o.start_pose[2] * M_PI / 180};
		driver.setGoal(randomGoal(fs, pose, rng));
	}

	VisualSimRun out;
	se2::Pose odometryPose = pose;
	const size_t steps = static_cast<size_t>(std::floor(o.duration / o.dt + 1e-9));
	const size_t framePeriod = o.stepsPerFrame();
	std::vector<double> kidnaps = o.kidnap_times;
	std::sort(kidnaps.begin(), kidnaps.end());
	size_t nextKidnap = 0;
	mrpt::system::CTicTac renderClock;

	for (size_t k = 1; k <= steps; k++)  // every entry holds an odometry increment
	{
		const double tRel = k * o.dt;
		const mrpt::Clock::time_point t = mrpt::Clock::fromDouble(kStartTime + tRel);
		auto action = mrpt::obs::CActionCollection::Create();
		double turnRate = 0;
		{
			const se2::Pose u = driver.step(pose);
			turnRate = u.phi / o.dt;
			const se2::Pose measured = o.odometry.measured(u, rng);
			pose = se2::compose(pose, u);
			if (se2::Pose slip; o.odometry.slip(rng, slip))
			{
				const se2::Pose slipped = se2::compose(pose, slip);
				if (fs.segmentIsFree({pose.x, pose.y}, {slipped.x, slipped.y})) pose = slipped, out.slips++;
			}
			odometryPose = se2::compose(odometryPose, measured);
			mrpt::obs::CActionRobotMovement2D mv;
			mv.computeFromOdometry(mrpt::poses::CPose2D(measured), {});
			mv.timestamp = t;
			action->insert(mv);
			if (nextKidnap < kidnaps.size() && tRel >= kidnaps[nextKidnap])
			{
				nextKidnap++;
				pose = kidnapTarget(o, fs, pose, rng, nextWaypoint);
				driver.setGoal(waypoints ? waypoint(o, nextWaypoint) : randomGoal(fs, pose, rng));
				out.kidnapSteps.push_back(k);
			}
		}
		out.truePath.push_back({kStartTime + tRel, pose});
		out.odometryPath.push_back({kStartTime + tRel, odometryPose});

		std::vector<world::Circle> people;
		for (size_t i = 0; i < events.peopleCount(); i++)
		{
			const auto p = events.person(i, tRel);
			world.placePerson(i, p.has_value(), p.value_or(Eigen::Vector2d(0, 0)));
			if (p) people.push_back({*p, world::WorldScene::kPersonRadius});
		}

		auto sf = mrpt::obs::CSensoryFrame::Create();
		sf->insert(laserScan(o, segments, people, pose, rng, t));
		if (k % framePeriod == 0)
		{
			renderClock.Tic();
			sf->insert(renderFrame(o, events, world, renderer, mount, pose, turnRate, k, t, imagesDir));
			out.renderSeconds += renderClock.Tac();
			out.images++;
			out.blackFrames += events.blackout(tRel);
			if (progress) progress(static_cast<double>(k) / steps);
		}
		out.entries.emplace_back(action, sf);
	}
	return out;
}
}  // namespace vslam

#include <libvslam/core/InputError.h>
#include <libvslam/sim/CVisualSimulator.h>
#include <libvslam/sim/CameraImaging.h>
#include <libvslam/sim/CameraRenderer.h>
#include <libvslam/sim/GoalDriver.h>
#include <libvslam/sim/RobotRoute.h>
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
constexpr double kDeg = M_PI / 180;

Eigen::Vector2d startPoint(const CVisualSimulator::TOptions& o)
{
	return o.path_type == CVisualSimulator::TOptions::PathType::Waypoints ? Eigen::Vector2d(o.waypoints[0], o.waypoints[1])
																 : Eigen::Vector2d(o.start_pose[0], o.start_pose[1]);
}

std::string describe(const Eigen::Vector2d& p)
{
	char buf[64];
	std::snprintf(buf, sizeof(buf), "(%.2f, %.2f)", p[0], p[1]);
	return buf;
}

mrpt::obs::CObservation2DRangeScan::Ptr laserScan(const CVisualSimulator::TOptions& o, const std::vector<world::Segment>& segs,
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

/** The robot's camera: renders the view (with the floor's jitter and the
 * occasional bump), makes the frame as the sensor does, writes it. Its
 * random draws have their own generator: they never change the path. */
class CameraFrames
{
   public:
	CameraFrames(const CVisualSimulator::TOptions& o, const std::string& imagesDir)
		: m_o(o), m_dir(imagesDir), m_renderer(o.camera), m_imaging(o.imaging, o.camera.fx(), o.seed),
		  m_mount(o.cameraPoseOnRobot()), m_rng(o.seed * 40503u + 7)
	{
	}

	mrpt::obs::CObservationImage::Ptr capture(const world::WorldScene& world, const SimulationEvents& events,
		const se2::Pose& robot, double turnRate, size_t k, mrpt::Clock::time_point t)
	{
		const double tRel = k * m_o.dt, frameDt = m_o.stepsPerFrame() * m_o.dt;
		FrameConditions f;
		f.lighting = events.lightingGain(tRel);
		f.blackout = events.blackout(tRel);
		f.turnRate = turnRate;
		f.dt = frameDt;
		f.whiteBalanceEpoch = events.lightingEpoch(tRel);
		f.noiseSeed = (static_cast<uint64_t>(m_o.seed) << 32) ^ k;
		double pitch = m_o.camera_jitter_deg * m_rng.drawGaussian1D_normalized();
		const double roll = m_o.camera_jitter_deg * m_rng.drawGaussian1D_normalized();
		if (m_rng.drawUniform(0, 1) < 1 - std::exp(-m_o.camera_bump_rate * frameDt))
		{
			pitch += 1.0 * m_rng.drawGaussian1D_normalized();
			f.bumpBlur = m_rng.drawUniform(3, 10) * m_o.camera.fy() / 250;
		}
		cv::Mat img = m_renderer.render(world.scene(),
			mrpt::poses::CPose3D(mrpt::poses::CPose2D(robot)) + m_mount + cameraShake(pitch * kDeg, roll * kDeg));
		m_imaging.capture(img, f);
		if (m_o.camera_grayscale) cv::cvtColor(img, img, cv::COLOR_BGR2GRAY);
		const bool jpg = m_o.image_format == "jpg";
		const std::string name = "img_" + std::to_string(k) + (jpg ? ".jpg" : ".png");
		const std::vector<int> params = jpg ? std::vector<int>{cv::IMWRITE_JPEG_QUALITY, m_o.jpeg_quality} : std::vector<int>{};
		if (!cv::imwrite(m_dir + "/" + name, img, params)) throw InputError("cannot write image '" + m_dir + "/" + name + "'");
		auto obs = mrpt::obs::CObservationImage::Create();
		obs->timestamp = t;
		obs->sensorLabel = "CAMERA";
		obs->cameraParams = m_o.camera;
		obs->cameraPose = m_mount;
		obs->image.setExternalStorage(name);
		return obs;
	}

   private:
	const CVisualSimulator::TOptions& m_o;
	std::string m_dir;
	CameraRenderer m_renderer;
	CameraImaging m_imaging;
	mrpt::poses::CPose3D m_mount;
	mrpt::random::CRandomGenerator m_rng;
};

/** People in the scene and as circles for the laser, at time t. */
std::vector<world::Circle> placePeople(const SimulationEvents& events, world::WorldScene& world, double t)
{
	std::vector<world::Circle> people;
	for (size_t i = 0; i < events.peopleCount(); i++)
	{
		const auto p = events.person(i, t);
		const PersonWalk& w = events.walk(i);
		world.placePerson(i, p.has_value(), p.value_or(Eigen::Vector2d(0, 0)), std::atan2(w.to[1] - w.from[1], w.to[0] - w.from[0]));
		if (p) people.push_back({*p, world::WorldScene::kPersonRadius});
	}
	return people;
}
}  // namespace

CVisualSimulator::CVisualSimulator(const CVisualSimulator::TOptions& options, const world::FloorPlan& plan)
	: m_options(options), m_plan(plan), m_free(m_plan, options.robot_radius, startPoint(options))
{
	const CVisualSimulator::TOptions& o = m_options;
	const FreeSpace& fs = m_free;
	const auto blocked = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const std::string& what) {
		if (const world::Segment* s = fs.blockingSegment(a, b))
			throw InputError(
				what + " " + describe(a) + " -> " + describe(b) + " runs through (or within " +
				std::to_string(o.robot_radius) + " m of) the obstacle on line " + std::to_string(s->line) +
				" of world file '" + m_plan.sourceFile + "'");
		if (!fs.isFree(b)) throw InputError(what + " ends at " + describe(b) + ", which is not free space");
	};
	if (o.path_type == CVisualSimulator::TOptions::PathType::Waypoints)
	{
		const size_t n = o.waypoints.size() / 2;
		for (size_t i = 0; i < n; i++)
		{
			const size_t j = (i + 1) % n;
			blocked({o.waypoints[2 * i], o.waypoints[2 * i + 1]}, {o.waypoints[2 * j], o.waypoints[2 * j + 1]},
				"[vslam_simul] waypoints: the leg from point " + std::to_string(i + 1));
		}
	}
	for (size_t i = 0; i + 5 < o.people.size(); i += 6)
	{
		const double* p = &o.people[i];
		if (const world::Segment* s = fs.blockingSegment({p[1], p[2]}, {p[3], p[4]}))
			throw InputError("[vslam_simul] people: person " + std::to_string(i / 6 + 1) +
				" walks through the obstacle on line " + std::to_string(s->line) + " of world file '" +
				m_plan.sourceFile + "'");
	}
}

mrpt::poses::CPose3D cameraShake(double pitchRad, double rollRad)
{
	// CPose3D turns by yaw about z, pitch about y, roll about x: the
	// camera's roll is its yaw and the camera's pitch its roll.
	return mrpt::poses::CPose3D(0, 0, 0, rollRad, 0, pitchRad);
}

VisualSimRun CVisualSimulator::run(const std::string& imagesDir, const std::function<void(double)>& progress) const
{
	const CVisualSimulator::TOptions& o = m_options;
	std::filesystem::create_directories(imagesDir);
	mrpt::random::CRandomGenerator rng(o.seed);  // robot, odometry, laser, kidnaps
	const SimulationEvents events(o, &m_free);
	world::WorldScene world(m_plan, events.peopleCount(), o.texture_max_side);
	CameraFrames camera(o, imagesDir);
	const std::vector<world::Segment> segments = m_plan.obstacleSegments();
	RobotRoute route(o, m_free, rng);

	TDriveOptions limits;
	limits.speed = o.speed, limits.maxTurnRate = o.max_turn_rate, limits.dt = o.dt;
	limits.turnInPlaceAbove = 0.15;  // drive nearly straight legs: they were checked for collisions
	limits.goalTolerance = 0.05;
	GoalDriver driver(limits, [&](const se2::Pose& p) { return route.nextGoal(p); });
	se2::Pose pose = route.start();
	driver.setGoal(route.firstGoal());

	VisualSimRun out;
	se2::Pose odometryPose = pose;
	const size_t steps = static_cast<size_t>(std::floor(o.duration / o.dt + 1e-9));
	std::vector<double> kidnaps = o.kidnap_times;
	std::sort(kidnaps.begin(), kidnaps.end());
	size_t nextKidnap = 0;
	mrpt::system::CTicTac renderClock;

	for (size_t k = 1; k <= steps && (o.laps == 0 || route.laps() < o.laps); k++)  // every entry holds an odometry increment
	{
		const double tRel = k * o.dt;
		const mrpt::Clock::time_point t = mrpt::Clock::fromDouble(kStartTime + tRel);
		auto action = mrpt::obs::CActionCollection::Create();
		const se2::Pose u = driver.step(pose);
		const double turnRate = u.phi / o.dt;
		const se2::Pose measured = o.odometry.measured(u, rng);
		pose = se2::compose(pose, u);
		if (se2::Pose slip; o.odometry.slip(rng, slip))
		{
			const se2::Pose slipped = se2::compose(pose, slip);
			if (m_free.segmentIsFree({pose.x, pose.y}, {slipped.x, slipped.y})) pose = slipped, out.slips++;
		}
		odometryPose = se2::compose(odometryPose, measured);
		mrpt::obs::CActionRobotMovement2D mv;
		mv.computeFromOdometry(mrpt::poses::CPose2D(measured), {});
		mv.timestamp = t;
		action->insert(mv);
		if (nextKidnap < kidnaps.size() && tRel >= kidnaps[nextKidnap])
		{
			nextKidnap++;
			Eigen::Vector2d goal;
			pose = route.kidnap(pose, goal);
			driver.setGoal(goal);
			out.kidnapSteps.push_back(k);
		}
		route.record(pose);
		out.truePath.push_back({kStartTime + tRel, pose});
		out.odometryPath.push_back({kStartTime + tRel, odometryPose});

		auto sf = mrpt::obs::CSensoryFrame::Create();
		sf->insert(laserScan(o, segments, placePeople(events, world, tRel), pose, rng, t));
		if (k % o.stepsPerFrame() == 0)
		{
			renderClock.Tic();
			sf->insert(camera.capture(world, events, pose, turnRate, k, t));
			out.renderSeconds += renderClock.Tac();
			out.images++;
			out.blackFrames += events.blackout(tRel);
			if (progress) progress(static_cast<double>(k) / steps);
		}
		out.entries.emplace_back(action, sf);
	}
	out.laps = route.laps();
	return out;
}
}  // namespace vslam

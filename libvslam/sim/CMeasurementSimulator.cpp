#include <libvslam/obs/CObservationLandmarkCreated.h>
#include <libvslam/obs/CObservationVisualLandmark.h>
#include <libvslam/sim/CMeasurementSimulator.h>
#include <libvslam/sim/GoalDriver.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/random/RandomGenerators.h>

#include <cmath>

using namespace vslam;
using Opt = CMeasurementSimulator::TOptions;

namespace
{
struct VisualLandmark
{
	int64_t id;
	se2::Pose createdAt;  //!< true robot pose at creation
	se2::Pose frame;  //!< the frame the front-end actually measures
	Eigen::Vector2d scene;  //!< centre of the landmark's scene
};

/** How a landmark's scene is seen from pose p: 0 if not recognizable, else
 * a quality in (0, 1] falling with viewpoint and scale change. */
double viewQuality(const Opt& o, const VisualLandmark& l, const se2::Pose& p)
{
	const Eigen::Vector2d toScene = l.scene - Eigen::Vector2d(p.x, p.y);
	const Eigen::Vector2d orig = l.scene - Eigen::Vector2d(l.createdAt.x, l.createdAt.y);
	const double bearing = se2::wrap(std::atan2(toScene[1], toScene[0]) - p.phi);
	if (std::abs(bearing) > 0.5 * o.camera_fov * 0.6) return 0;  // central part
	const double viewChange = std::abs(se2::wrap(
		std::atan2(toScene[1], toScene[0]) - std::atan2(orig[1], orig[0])));
	if (viewChange > o.max_view_change) return 0;
	const double scale = toScene.norm() / orig.norm();
	const double logScale = std::abs(std::log(scale));
	if (logScale > std::log(o.max_scale_change)) return 0;
	return (1 - viewChange / std::max(o.max_view_change, 1e-9)) *
		(1 - logScale / std::max(std::log(o.max_scale_change), 1e-9));
}

/** Random goals keep the wall margin. */
Eigen::Vector2d randomGoal(const Opt& o, mrpt::random::CRandomGenerator& rng)
{
	const double m = o.wall_margin;
	return {rng.drawUniform(m, o.room_width - m), rng.drawUniform(m, o.room_height - m)};
}

double gauss(mrpt::random::CRandomGenerator& rng, double std)
{
	return std * rng.drawGaussian1D_normalized();
}
/** What the simulation draws from and keeps between steps. */
struct SimulationState
{
	const Opt& o;
	mrpt::random::CRandomGenerator& rng;
	SimulatedRun& out;
	std::vector<VisualLandmark> visual;
	std::vector<Eigen::Vector2d> points;  //!< range-bearing landmarks
};

/** The range-bearing beacons, uniformly over the room. */
void placePointLandmarks(SimulationState& sim)
{
	const Opt& o = sim.o;
	for (uint32_t i = 0; i < o.point_landmarks; i++)
	{
		sim.points.emplace_back(sim.rng.drawUniform(0, o.room_width), sim.rng.drawUniform(0, o.room_height));
		sim.out.landmarks.push_back(
			{{LandmarkKind::Point, int64_t(i + 1)}, {sim.points.back()[0], sim.points.back()[1], 0}, true});
	}
}

/** Where a kidnapped robot is put: a random pose at least
 * kidnap_min_distance away (when the room allows it). */
se2::Pose kidnapTarget(const Opt& o, mrpt::random::CRandomGenerator& rng, const se2::Pose& from)
{
	se2::Pose to;
	do
	{
		const Eigen::Vector2d g = randomGoal(o, rng);
		to = {g[0], g[1], rng.drawUniform(-M_PI, M_PI)};
	} while (std::hypot(to.x - from.x, to.y - from.y) < o.kidnap_min_distance &&
		o.kidnap_min_distance < std::hypot(o.room_width, o.room_height) - 2 * o.wall_margin);
	return to;
}

/** A recognition of landmark l from pose: a good measurement with the
 * configured noise (sometimes attributed to another landmark), or a bad one. */
CObservationVisualLandmark::Ptr recognition(
	SimulationState& sim, const VisualLandmark& l, const se2::Pose& pose, double quality, bool recorded)
{
	const Opt& o = sim.o;
	auto& rng = sim.rng;
	auto m = CObservationVisualLandmark::Create();
	m->landmarkID = l.id;
	se2::Pose z = se2::between(pose, l.frame);
	if (rng.drawUniform(0, 1) < o.bad_measurement_probability)
	{
		sim.out.badMeasurements += recorded;
		z = {z.x + gauss(rng, 0.5), z.y + gauss(rng, 0.5), se2::wrap(z.phi + gauss(rng, 0.35))};
		m->ProjErrRMS = rng.drawUniform(3.5, 10.0);
		m->NPoints = static_cast<uint32_t>(rng.drawUniform(3, 30));
		m->Slope = gauss(rng, 0.2);
	}
	else
	{
		z = {z.x + gauss(rng, o.meas_std_dx), z.y + gauss(rng, o.meas_std_dy), se2::wrap(z.phi + gauss(rng, o.meas_std_dphi))};
		m->ProjErrRMS = std::abs(0.8 + gauss(rng, 0.4));
		m->NPoints = static_cast<uint32_t>(15 + 60 * quality * rng.drawUniform(0.7, 1.0));
		m->Slope = gauss(rng, 0.02);
		if (sim.visual.size() > 1 && rng.drawUniform(0, 1) < o.false_recognition_probability)
		{
			sim.out.falseRecognitions += recorded;
			int64_t other;
			do
				other = sim.visual[rng.drawUniform32bit() % sim.visual.size()].id;
			while (other == l.id);
			m->landmarkID = other;
		}
	}
	m->relPose = mrpt::poses::CPose2D(z);
	return m;
}

/** A new landmark where the robot is (its frame off by the front-end's
 * error, its scene some way ahead). */
void createVisualLandmark(SimulationState& sim, const se2::Pose& pose, SimulatedStep& st, bool recorded)
{
	const Opt& o = sim.o;
	auto& rng = sim.rng;
	VisualLandmark l;
	l.id = static_cast<int64_t>(sim.visual.size() + 1);
	l.createdAt = pose;
	l.frame = se2::compose(pose,
		{gauss(rng, o.landmark_frame_std_xy), gauss(rng, o.landmark_frame_std_xy), gauss(rng, o.landmark_frame_std_phi)});
	const double depth = rng.drawUniform(o.scene_depth_min, o.scene_depth_max);
	l.scene = {pose.x + depth * std::cos(pose.phi), pose.y + depth * std::sin(pose.phi)};
	sim.visual.push_back(l);
	sim.out.landmarks.push_back({{LandmarkKind::Pose, l.id}, l.frame, !recorded});
	auto c = CObservationLandmarkCreated::Create();
	c->timestamp = st.t;
	c->landmarkID = l.id;
	c->NPoints = 100;
	c->NViews = 3;
	if (recorded)
	{
		st.sf->insert(c);
		sim.out.creations++;
	}
}

/** The front-end's outputs at an image: recognitions of the landmarks in
 * view, or a new landmark where none is recognized or near. */
void observeVisual(SimulationState& sim, const se2::Pose& pose, SimulatedStep& st, bool recorded)
{
	const Opt& o = sim.o;
	bool recognizedAny = false, nearSimilar = false;
	for (const auto& l : sim.visual)
	{
		const double dist = std::hypot(pose.x - l.createdAt.x, pose.y - l.createdAt.y);
		const double ang = std::abs(se2::wrap(pose.phi - l.createdAt.phi));
		if (dist < o.creation_min_distance && ang < o.creation_min_angle) nearSimilar = true;
		const double quality = viewQuality(o, l, pose);
		if (quality <= 0) continue;
		if (sim.rng.drawUniform(0, 1) >= o.recognition_probability) continue;
		recognizedAny = true;
		auto m = recognition(sim, l, pose, quality, recorded);
		m->timestamp = st.t;
		st.sf->insert(m);
		sim.out.visualMeasurements += recorded;
	}
	if (!recognizedAny && !nearSimilar) createVisualLandmark(sim, pose, st, recorded);
}

/** The range-bearing sensor's view of the beacons. */
void observeRangeBearing(SimulationState& sim, const se2::Pose& pose, SimulatedStep& st, bool recorded)
{
	const Opt& o = sim.o;
	const mrpt::poses::CPose3D sensorPose(0.1, 0.0, 0.2, 0, 0, 0);
	auto br = mrpt::obs::CObservationBearingRange::Create();
	br->timestamp = st.t;
	br->sensorLabel = "RB";
	br->sensorLocationOnRobot = sensorPose;
	br->maxSensorDistance = static_cast<float>(o.rb_max_range);
	br->fieldOfView_yaw = static_cast<float>(o.rb_fov);
	br->sensor_std_range = static_cast<float>(o.rb_std_range);
	br->sensor_std_yaw = static_cast<float>(o.rb_std_bearing);
	const se2::Pose sensor = se2::compose(pose, {sensorPose.x(), sensorPose.y(), sensorPose.yaw()});
	for (size_t i = 0; i < sim.points.size(); i++)
	{
		const double dx = sim.points[i][0] - sensor.x, dy = sim.points[i][1] - sensor.y;
		const double r = std::hypot(dx, dy);
		const double b = se2::wrap(std::atan2(dy, dx) - sensor.phi);
		if (r > o.rb_max_range || std::abs(b) > o.rb_fov / 2) continue;
		mrpt::obs::CObservationBearingRange::TMeasurement m;
		m.range = static_cast<float>(r + gauss(sim.rng, o.rb_std_range));
		m.yaw = static_cast<float>(se2::wrap(b + gauss(sim.rng, o.rb_std_bearing)));
		m.pitch = 0;
		m.landmarkID = static_cast<int32_t>(i + 1);
		br->sensedData.push_back(m);
		sim.out.rangeBearingMeasurements += recorded;
	}
	if (!br->sensedData.empty()) st.sf->insert(br);
}

/** The odometry increment as MRPT's action. */
mrpt::obs::CActionCollection::Ptr actionOf(const se2::Pose& increment, mrpt::Clock::time_point t)
{
	auto action = mrpt::obs::CActionCollection::Create();
	mrpt::obs::CActionRobotMovement2D mv;
	mv.computeFromOdometry(mrpt::poses::CPose2D(increment), mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
	mv.timestamp = t;
	action->insert(mv);
	return action;
}
}  // namespace

SimulatedRun CMeasurementSimulator::run() const
{
	const Opt& o = m_options;
	mrpt::random::CRandomGenerator rng(o.seed);
	size_t nextWaypoint = 0;
	const auto waypoint = [&](size_t i) {
		const size_t n = o.waypoints.size() / 2;
		return Eigen::Vector2d(o.waypoints[2 * (i % n)], o.waypoints[2 * (i % n) + 1]);
	};
	TDriveOptions limits;
	limits.speed = o.speed, limits.maxTurnRate = o.max_turn_rate, limits.dt = o.dt;
	GoalDriver driver(limits, [&](const se2::Pose&) {
		return o.path_type == Opt::PathType::Waypoints ? waypoint(++nextWaypoint) : randomGoal(o, rng);
	});
	const TOdometryErrorModel odometry = o.odometryErrors();
	SimulatedRun out;
	SimulationState sim{o, rng, out, {}, {}};
	if (o.landmark_type == Opt::LandmarkType::RangeBearing) placePointLandmarks(sim);

	const size_t mappingSteps = static_cast<size_t>(std::floor(o.mapping_duration / o.dt));
	const size_t steps = mappingSteps + static_cast<size_t>(std::floor(o.duration / o.dt));
	const size_t framePeriod = std::max<size_t>(1, static_cast<size_t>(std::lround(1.0 / (o.camera_rate * o.dt))));
	size_t nextKidnap = 0;
	std::vector<double> kidnaps = o.kidnap_times;
	std::sort(kidnaps.begin(), kidnaps.end());

	se2::Pose pose;
	if (o.path_type == Opt::PathType::Waypoints)
	{
		driver.setGoal(waypoint(nextWaypoint = 1));
		const Eigen::Vector2d p0 = waypoint(0), g = driver.goal();
		pose = {p0[0], p0[1], std::atan2(g[1] - p0[1], g[0] - p0[0])};
	}
	else
	{
		driver.setGoal(randomGoal(o, rng));
		pose = {o.room_width / 2, o.room_height / 2, 0};
	}
	for (size_t k = 1; k <= steps; k++)
	{
		SimulatedStep st;
		const bool recorded = k > mappingSteps;
		st.t = mrpt::Clock::fromDouble(kStartTime + (k - mappingSteps) * o.dt);

		// True motion and what odometry reports.
		const se2::Pose u = driver.step(pose);
		st.odometryIncrement = odometry.measured(u, rng);
		pose = se2::compose(pose, u);
		if (se2::Pose slip; odometry.slip(rng, slip)) pose = se2::compose(pose, slip);
		pose.x = std::clamp(pose.x, 0.0, o.room_width);
		pose.y = std::clamp(pose.y, 0.0, o.room_height);
		if (recorded && nextKidnap < kidnaps.size() && (k - mappingSteps) * o.dt >= kidnaps[nextKidnap])
		{
			nextKidnap++;
			pose = kidnapTarget(o, rng, pose);
			st.kidnappedHere = true;
		}
		st.truePose = pose;
		st.action = actionOf(st.odometryIncrement, st.t);
		st.sf = mrpt::obs::CSensoryFrame::Create();
		if (k % framePeriod == 0)
		{
			if (o.landmark_type == Opt::LandmarkType::Visual)
				observeVisual(sim, pose, st, recorded);
			else
				observeRangeBearing(sim, pose, st, recorded);
		}
		if (recorded) out.steps.push_back(std::move(st));
	}
	return out;
}

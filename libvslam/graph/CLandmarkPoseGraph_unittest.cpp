#include <gtest/gtest.h>
#include <libvslam/graph/CLandmarkPoseGraph.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <tests/support/Measurements.h>

#include <cmath>

using namespace vslam;

namespace
{
using Clock = mrpt::Clock;

Clock::time_point at(double s)
{
	return Clock::time_point() + std::chrono::microseconds(static_cast<int64_t>(s * 1e6));
}

/** The landmark seen from the robot, with that noise. */
LandmarkMeasurement measurement(const se2::Pose& robot, const se2::Pose& landmark, double stdXY,
	double stdPhi)
{
	return vslam::testing::poseMeasurement(0, se2::between(robot, landmark), stdXY, stdPhi);
}

double positionError(const se2::Pose& a, const se2::Pose& b) { return std::hypot(a.x - b.x, a.y - b.y); }

/** A robot drives around a 4 m x 4 m square (1 m steps, turning 90 deg at
 * the corners) whose odometry reports 4 deg too little per turn. At every
 * corner it creates a landmark where it stands; at the end it measures the
 * first landmark again. The guess handed to the graph is dead reckoning. */
struct SquareRun
{
	CLandmarkPoseGraph graph;
	se2::Pose truth{0, 0, 0}, deadReckoning{0, 0, 0};
	std::vector<se2::Pose> trueLandmarks;
	double t = 0;
	bool closedLoop = false;

	explicit SquareRun(const CLandmarkPoseGraph::TOptions& o) : graph(o, {0, 0, 0}) {}

	void step(const se2::Pose& trueIncrement, const se2::Pose& reportedIncrement)
	{
		truth = se2::compose(truth, trueIncrement);
		deadReckoning = se2::compose(deadReckoning, reportedIncrement);
		Eigen::Matrix3d cov = Eigen::Vector3d(0.01 * 0.01, 0.01 * 0.01, std::pow(2.0 * M_PI / 180, 2))
								  .asDiagonal();
		graph.addOdometry(reportedIncrement, cov);
		t += 5;
		graph.addKeyframe(at(t), deadReckoning);
	}

	void run()
	{
		const double turnError = 4 * M_PI / 180;
		graph.addKeyframe(at(0), truth);
		graph.placeLandmark(0, measurement(truth, truth, 0.01, 0.01));
		trueLandmarks.push_back(truth);
		for (int side = 0; side < 4; side++)
		{
			for (int k = 0; k < 4; k++) step({1, 0, 0}, {1, 0, 0});
			step({0, 0, M_PI / 2}, {0, 0, M_PI / 2 - turnError});
			if (side < 3)
			{
				graph.placeLandmark(side + 1, measurement(truth, truth, 0.01, 0.01));
				trueLandmarks.push_back(truth);
			}
		}
		closedLoop = graph.addMeasurement(0, measurement(truth, trueLandmarks[0], 0.01, 0.01));
	}
};
}  // namespace

TEST(CLandmarkPoseGraph, ALoopClosureStraightensTheSquare)
{
	SquareRun run{CLandmarkPoseGraph::TOptions()};
	run.run();
	EXPECT_TRUE(run.closedLoop);
	// Dead reckoning is 16 deg and 0.8 m off at the end.
	ASSERT_GT(positionError(run.deadReckoning, run.truth), 0.5);
	const auto c = run.graph.optimize();
	EXPECT_EQ(c.leftOutEdges, 0u);
	// The last keyframe sees the first landmark (5 cm from it, 1 cm
	// measurement noise), so it ends up next to the truth.
	EXPECT_LT(positionError(c.keyframe, run.truth), 0.05);
	EXPECT_LT(std::abs(se2::wrap(c.keyframe.phi - run.truth.phi)), 1.0 * M_PI / 180);
	// The landmarks are corrected along the loop: the error that was up to
	// 12 deg of heading is spread over 4 turns.
	ASSERT_EQ(c.landmarks.size(), 4u);
	for (const auto& [slot, kind, pose] : c.landmarks)
	{
		EXPECT_LT(positionError(pose, run.trueLandmarks.at(slot)), 0.5) << "slot " << slot;
		EXPECT_LT(std::abs(se2::wrap(pose.phi - run.trueLandmarks.at(slot).phi)), 4.0 * M_PI / 180)
			<< "slot " << slot;
	}
	// Slot 2 (the far corner) was 8 deg off in dead reckoning; the loop
	// halves that at least.
	const auto& far = c.landmarks.at(2).pose;
	EXPECT_LT(std::abs(se2::wrap(far.phi - run.trueLandmarks[2].phi)), 4.0 * M_PI / 180);
}

TEST(CLandmarkPoseGraph, AMeasurementClosesALoopOnlyAfterTheGap)
{
	CLandmarkPoseGraph::TOptions o;
	o.min_gap_s = 20;
	CLandmarkPoseGraph graph(o, {0, 0, 0});
	graph.addKeyframe(at(0), {0, 0, 0});
	graph.placeLandmark(7, measurement({0, 0, 0}, {1, 0, 0}, 0.01, 0.01));
	EXPECT_TRUE(graph.hasLandmark(7));
	EXPECT_FALSE(graph.hasLandmark(8));
	graph.addKeyframe(at(10), {0, 0, 0});
	EXPECT_FALSE(graph.addMeasurement(7, measurement({0, 0, 0}, {1, 0, 0}, 0.01, 0.01)));
	graph.addKeyframe(at(25), {0, 0, 0});
	EXPECT_FALSE(graph.addMeasurement(7, measurement({0, 0, 0}, {1, 0, 0}, 0.01, 0.01)));
	graph.addKeyframe(at(45), {0, 0, 0});
	EXPECT_TRUE(graph.addMeasurement(7, measurement({0, 0, 0}, {1, 0, 0}, 0.01, 0.01)));
	EXPECT_EQ(graph.keyframes(), 4u);
}

TEST(CLandmarkPoseGraph, AWrongMeasurementIsGatedOut)
{
	SquareRun run{CLandmarkPoseGraph::TOptions()};
	run.run();
	// The robot drives on and measures landmarks 2 and 1 correctly; then,
	// while it measures landmark 0, a false recognition of landmark 2 comes
	// in, 1 m and 30 deg off.
	run.step({1, 0, 0}, {1, 0, 0});
	run.graph.addMeasurement(2, measurement(run.truth, run.trueLandmarks[2], 0.01, 0.01));
	run.graph.addMeasurement(1, measurement(run.truth, run.trueLandmarks[1], 0.01, 0.01));
	run.step({0.5, 0, 0}, {0.5, 0, 0});
	run.graph.addMeasurement(0, measurement(run.truth, run.trueLandmarks[0], 0.01, 0.01));
	LandmarkMeasurement wrong = measurement(run.truth, run.trueLandmarks[2], 0.01, 0.01);
	wrong.z[0] += 1;
	wrong.z[2] += 30 * M_PI / 180;
	run.graph.addMeasurement(2, wrong);
	const auto c = run.graph.optimize();
	EXPECT_GE(c.leftOutEdges, 1u);
	EXPECT_LT(positionError(c.keyframe, run.truth), 0.05);
	EXPECT_LT(positionError(c.landmarks.at(2).pose, run.trueLandmarks[2]), 0.5);
}

TEST(CLandmarkPoseGraph, LostOdometryDoesNotPullTheKeyframe)
{
	CLandmarkPoseGraph graph(CLandmarkPoseGraph::TOptions(), {0, 0, 0});
	graph.addKeyframe(at(0), {0, 0, 0});
	const se2::Pose landmark{2, 1, 0.3};
	graph.placeLandmark(0, measurement({0, 0, 0}, landmark, 0.01, 0.01));
	// Kidnapped: the robot is carried to (3, 3, 1) while odometry says it
	// stood still, then it measures the landmark.
	graph.addOdometry({0, 0, 0}, Eigen::Matrix3d::Identity() * 1e-4);
	graph.loseOdometry();
	graph.addKeyframe(at(30), {0, 0, 0});
	const se2::Pose robot{3, 3, 1};
	graph.addMeasurement(0, measurement(robot, landmark, 0.01, 0.01));
	const auto c = graph.optimize();
	EXPECT_EQ(c.leftOutEdges, 0u);
	EXPECT_LT(positionError(c.keyframe, robot), 0.01);
	EXPECT_LT(positionError(c.landmarks.at(0).pose, landmark), 0.01);
}

TEST(CLandmarkPoseGraph, ThinningKeepsTheCapAndTheSolution)
{
	// Two laps of the square. Between the corners the keyframes have only
	// odometry edges, whose composition loses nothing; the second lap's
	// corner measurements may go with their keyframes. The thinned graph's
	// solution stays within a few millimetres of the full one's.
	CLandmarkPoseGraph::TOptions capped, unlimited;
	capped.max_keyframes = 12;
	unlimited.max_keyframes = 0;
	SquareRun thinned{capped}, full{unlimited};
	for (SquareRun* run : {&thinned, &full})
	{
		run->run();
		for (int side = 0; side < 4; side++)
		{
			for (int k = 0; k < 4; k++) run->step({1, 0, 0}, {1, 0, 0});
			run->step({0, 0, M_PI / 2}, {0, 0, M_PI / 2 - 4 * M_PI / 180});
			run->graph.addMeasurement(static_cast<size_t>((side + 1) % 4),
				measurement(run->truth, run->trueLandmarks[static_cast<size_t>((side + 1) % 4)], 0.01, 0.01));
		}
	}
	EXPECT_EQ(full.graph.keyframes(), 41u);
	EXPECT_LE(thinned.graph.keyframes(), 12u);
	EXPECT_LT(thinned.graph.nodes(), full.graph.nodes());
	const auto a = thinned.graph.optimize(), b = full.graph.optimize();
	EXPECT_LT(positionError(a.keyframe, b.keyframe), 0.01);
	EXPECT_LT(std::abs(se2::wrap(a.keyframe.phi - b.keyframe.phi)), 0.2 * M_PI / 180);
	ASSERT_EQ(a.landmarks.size(), b.landmarks.size());
	for (size_t i = 0; i < a.landmarks.size(); i++)
	{
		EXPECT_LT(positionError(a.landmarks[i].pose, b.landmarks[i].pose), 0.01) << "slot " << i;
		EXPECT_LT(std::abs(se2::wrap(a.landmarks[i].pose.phi - b.landmarks[i].pose.phi)), 0.2 * M_PI / 180);
	}
	// The smoothed path keeps the keyframes that are left, in time order.
	const auto path = thinned.graph.keyframePath();
	ASSERT_EQ(path.size(), thinned.graph.keyframes());
	for (size_t i = 1; i < path.size(); i++) EXPECT_LT(path[i - 1].first, path[i].first);
}

TEST(CLandmarkPoseGraph, ThinningDropsTheMeasurementsOfRemovedKeyframes)
{
	// A robot walks 12 m past a landmark, measuring it at every keyframe
	// with odometry 5% long: a removed keyframe takes its measurement edge
	// along, and the rest still correct the path.
	const auto walk = [](uint32_t maxKeyframes, se2::Pose& truth) {
		CLandmarkPoseGraph::TOptions o;
		o.max_keyframes = maxKeyframes;
		CLandmarkPoseGraph graph(o, {0, 0, 0});
		se2::Pose guess{0, 0, 0};
		truth = {0, 0, 0};
		const Eigen::Matrix3d cov = Eigen::Vector3d(1e-4, 1e-4, 1e-4).asDiagonal();
		graph.addKeyframe(at(0), truth);
		graph.placeLandmark(0, measurement(truth, {1, 1, 0}, 0.01, 0.01));
		for (int k = 1; k <= 60; k++)
		{
			truth = se2::compose(truth, {0.2, 0, 0});
			guess = se2::compose(guess, {0.21, 0, 0});
			graph.addOdometry({0.21, 0, 0}, cov);
			graph.addKeyframe(at(k), guess);
			graph.addMeasurement(0, measurement(truth, {1, 1, 0}, 0.01, 0.01));
			EXPECT_LE(graph.keyframes(), maxKeyframes > 0 ? maxKeyframes : 61u) << "after keyframe " << k;
		}
		return graph;
	};
	se2::Pose truth;
	auto thinned = walk(20, truth);
	auto full = walk(0, truth);
	// Creation and the first keyframe's (empty) odometry, then odometry and
	// a measurement per keyframe.
	EXPECT_EQ(full.edges(), 2u + 2 * 60);
	EXPECT_LE(thinned.edges(), 2u + 2 * 20);
	const auto a = thinned.optimize(), b = full.optimize();
	EXPECT_EQ(a.leftOutEdges, 0u);
	// Dead reckoning ends 0.6 m off. The landmark, 11 m behind at the end,
	// is measured with 0.6 deg of heading noise: 0.055 m with every
	// measurement, 0.107 m with the thinned graph's (measured).
	EXPECT_LT(positionError(b.keyframe, truth), 0.1);
	EXPECT_LT(positionError(a.keyframe, truth), 0.2);
}

namespace
{
/** Range and bearing of point (px, py) from the sensor at robot (+) sensor. */
LandmarkMeasurement rangeBearingOf(const se2::Pose& robot, const se2::Pose& sensor, int64_t id,
	const Eigen::Vector2d& point, double stdRange, double stdBearing)
{
	const se2::Pose s = se2::compose(robot, sensor);
	const double dx = point.x() - s.x, dy = point.y() - s.y;
	return vslam::testing::rangeBearingMeasurement(
		id, std::hypot(dx, dy), se2::wrap(std::atan2(dy, dx) - s.phi), stdRange, stdBearing, sensor);
}

/** The square of SquareRun driven with range-bearing beacons 1 m outside
 * its corners instead of pose landmarks: every keyframe measures the
 * beacons within 3 m, from a sensor 10 cm ahead of the robot's centre.
 * With outlierAt >= 0, that keyframe also reports beacon 0 where beacon 2
 * is (a wrong association). */
struct PointSquareRun
{
	CLandmarkPoseGraph graph{CLandmarkPoseGraph::TOptions(), {0, 0, 0}};
	se2::Pose truth{0, 0, 0}, deadReckoning{0, 0, 0};
	const se2::Pose sensor{0.1, 0, 0};
	const std::vector<Eigen::Vector2d> beacons{{-1, -1}, {5, -1}, {5, 5}, {-1, 5}};
	std::vector<bool> placed = std::vector<bool>(4, false);
	int keyframe = 0;
	int outlierAt = -1;

	void observe()
	{
		graph.addKeyframe(at(5.0 * keyframe), deadReckoning);
		for (size_t b = 0; b < beacons.size(); b++)
		{
			if (positionError(truth, {beacons[b].x(), beacons[b].y(), 0}) > 3) continue;
			const auto m = rangeBearingOf(truth, sensor, static_cast<int64_t>(b), beacons[b], 0.02, 0.01);
			if (placed[b])
				graph.addMeasurement(b, m);
			else
				graph.placeLandmark(b, m), placed[b] = true;
		}
		if (keyframe == outlierAt)
			graph.addMeasurement(0, rangeBearingOf(truth, sensor, 0, beacons[2], 0.02, 0.01));
		keyframe++;
	}

	void step(const se2::Pose& trueIncrement, const se2::Pose& reportedIncrement)
	{
		truth = se2::compose(truth, trueIncrement);
		deadReckoning = se2::compose(deadReckoning, reportedIncrement);
		graph.addOdometry(reportedIncrement,
			Eigen::Vector3d(0.01 * 0.01, 0.01 * 0.01, std::pow(2.0 * M_PI / 180, 2)).asDiagonal());
		observe();
	}

	void run()
	{
		const double turnError = 4 * M_PI / 180;
		observe();
		for (int side = 0; side < 4; side++)
		{
			for (int k = 0; k < 4; k++) step({1, 0, 0}, {1, 0, 0});
			step({0, 0, M_PI / 2}, {0, 0, M_PI / 2 - turnError});
		}
	}
};
}  // namespace

TEST(CLandmarkPoseGraph, RangeBearingBeaconsStraightenTheSquare)
{
	PointSquareRun run;
	run.run();
	ASSERT_GT(positionError(run.deadReckoning, run.truth), 0.5);
	const auto c = run.graph.optimize();
	EXPECT_EQ(c.leftOutEdges, 0u);
	// 2 cm and 0.6 deg per measurement, 21 keyframes: the end is back on
	// the truth, in position and heading (which only the beacons' geometry
	// fixes: a point has none).
	EXPECT_LT(positionError(c.keyframe, run.truth), 0.03);
	EXPECT_LT(std::abs(se2::wrap(c.keyframe.phi - run.truth.phi)), 0.5 * M_PI / 180);
	ASSERT_EQ(c.landmarks.size(), 4u);
	for (const auto& [slot, kind, pose] : c.landmarks)
	{
		EXPECT_EQ(kind, LandmarkKind::Point);
		EXPECT_LT(std::hypot(pose.x - run.beacons[slot].x(), pose.y - run.beacons[slot].y()), 0.03)
			<< "slot " << slot;
	}
}

TEST(CLandmarkPoseGraph, AWrongBeaconAssociationIsLeftOut)
{
	PointSquareRun run;
	run.outlierAt = 12;  // near beacon 2, 6 m from beacon 0
	run.run();
	const auto c = run.graph.optimize();
	EXPECT_EQ(c.leftOutEdges, 1u);
	EXPECT_LT(positionError(c.keyframe, run.truth), 0.03);
	for (const auto& [slot, kind, pose] : c.landmarks)
		EXPECT_LT(std::hypot(pose.x - run.beacons[slot].x(), pose.y - run.beacons[slot].y()), 0.03)
			<< "slot " << slot;
}

TEST(CLandmarkPoseGraph, OptionsRoundTripThroughTheIni)
{
	CLandmarkPoseGraph::TOptions o;
	o.enabled = false;
	o.min_gap_s = 12.5;
	o.edge_gate_probability = 0.99;
	o.max_keyframes = 321;
	mrpt::config::CConfigFileMemory written;
	o.saveToConfigFile(written, o.kSection);
	std::string text;
	written.getContent(text);
	const mrpt::config::CConfigFileMemory ini(text);
	CLandmarkPoseGraph::TOptions back;
	back.loadFromConfigFile(ini, back.kSection);
	EXPECT_EQ(back.enabled, false);
	EXPECT_DOUBLE_EQ(back.min_gap_s, 12.5);
	EXPECT_DOUBLE_EQ(back.edge_gate_probability, 0.99);
	EXPECT_EQ(back.max_keyframes, 321u);
}

#pragma once
/** \file Measurements.h  Small builders for filter inputs in tests. */
#include <libvslam/filter/CMeasurementExtractor.h>

namespace vslam::testing
{
inline LandmarkMeasurement poseMeasurement(
	int64_t id, const se2::Pose& z, double stdXY = 0.09, double stdPhi = 0.0436)
{
	LandmarkMeasurement m;
	m.key = {LandmarkKind::Pose, id};
	m.z.resize(3);
	m.z << z.x, z.y, z.phi;
	m.R = MatN::Zero(3, 3);
	m.R.diagonal() << stdXY * stdXY, stdXY * stdXY, stdPhi * stdPhi;
	return m;
}

/** A pose landmark at p, its covariance var times the identity. */
inline LandmarkEstimate poseLandmark(const se2::Pose& p, double var = 1e-4)
{
	LandmarkEstimate l;
	l.kind = LandmarkKind::Pose;
	l.mean = se2::toVector(p);
	l.cov = Eigen::Matrix3d::Identity() * var;
	return l;
}

inline LandmarkMeasurement rangeBearingMeasurement(
	int64_t id, double range, double bearing, double stdR = 0.05,
	double stdB = 0.02, const se2::Pose& sensor = {0, 0, 0})
{
	LandmarkMeasurement m;
	m.key = {LandmarkKind::Point, id};
	m.z.resize(2);
	m.z << range, bearing;
	m.R = MatN::Zero(2, 2);
	m.R.diagonal() << stdR * stdR, stdB * stdB;
	m.sensorPose = sensor;
	return m;
}

/** A point landmark at xy, its covariance var times the identity. */
inline LandmarkEstimate pointLandmark(const Eigen::Vector2d& xy, double var = 1e-4)
{
	LandmarkEstimate l;
	l.kind = LandmarkKind::Point;
	l.mean << xy, 0;
	l.cov.topLeftCorner<2, 2>() = Eigen::Matrix2d::Identity() * var;
	return l;
}

/** The exact range and bearing of the point landmark at xy from `robot`. */
inline LandmarkMeasurement rangeBearingFrom(const se2::Pose& robot, int64_t id, const Eigen::Vector2d& xy)
{
	const double dx = xy[0] - robot.x, dy = xy[1] - robot.y;
	return rangeBearingMeasurement(id, std::hypot(dx, dy), se2::wrap(std::atan2(dy, dx) - robot.phi));
}

inline LandmarkCreation creation(int64_t id)
{
	LandmarkCreation c;
	c.key = {LandmarkKind::Pose, id};
	c.relative.key = c.key;
	c.relative.z = VecN::Zero(3);
	c.relative.R = MatN::Zero(3, 3);
	return c;
}

inline FrameMeasurements frame(
	double t, std::vector<LandmarkMeasurement> ms,
	std::vector<LandmarkCreation> cs = {})
{
	FrameMeasurements f;
	f.timestamp = mrpt::Clock::fromDouble(t);
	f.measurements = std::move(ms);
	f.creations = std::move(cs);
	return f;
}
}  // namespace vslam::testing

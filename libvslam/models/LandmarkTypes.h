#pragma once
/** \file LandmarkTypes.h
 * What the filter knows about one landmark in one particle, and what one
 * landmark measurement says. Two kinds share these types:
 *  - Pose landmarks (the paper's visual landmarks): state (x, y, phi), the
 *    landmark frame in the world; measurement (dx, dy, dphi), that frame in
 *    the robot frame.
 *  - Point landmarks (range-bearing beacons, e.g. MRCLAM): state (x, y);
 *    measurement (range, bearing) from a sensor mounted on the robot.
 */
#include <libvslam/models/Gaussian.h>
#include <libvslam/models/SE2.h>

#include <Eigen/Core>
#include <cstdint>
#include <functional>

namespace vslam
{
enum class LandmarkKind : uint8_t
{
	Pose = 0,
	Point = 1
};

inline const char* toString(LandmarkKind k)
{
	return k == LandmarkKind::Pose ? "pose" : "point";
}

/** State dimension of a landmark kind. */
inline int stateDim(LandmarkKind k) { return k == LandmarkKind::Pose ? 3 : 2; }

/** Landmarks are identified by kind and ID: visual and range-bearing IDs
 * live in separate name spaces. */
struct LandmarkKey
{
	LandmarkKind kind = LandmarkKind::Pose;
	int64_t id = -1;
	bool operator==(const LandmarkKey& o) const
	{
		return kind == o.kind && id == o.id;
	}
};

struct LandmarkKeyHash
{
	size_t operator()(const LandmarkKey& k) const
	{
		return std::hash<int64_t>()(k.id) * 31u + static_cast<size_t>(k.kind);
	}
};

/** One landmark's Kalman filter in one particle's bank. For point
 * landmarks only the leading 2 entries / 2x2 block are used. */
struct LandmarkEstimate
{
	Eigen::Vector3d mean = Eigen::Vector3d::Zero();
	Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
	LandmarkKind kind = LandmarkKind::Pose;
	/** Kalman updates applied to this estimate. */
	uint32_t updates = 0;

	int dim() const { return stateDim(kind); }
	/** The used block of mean / cov. */
	VecN meanN() const { return mean.head(dim()); }
	MatN covN() const { return cov.topLeftCorner(dim(), dim()); }
};

/** One measurement of one landmark, ready for the filter. */
struct LandmarkMeasurement
{
	LandmarkKey key;
	/** Pose kind: (dx, dy, dphi). Point kind: (range, bearing). */
	VecN z;
	/** Measurement noise covariance (3x3 or 2x2). */
	MatN R;
	/** Sensor pose on the robot (point kind; identity for pose kind, whose
	 * measurement is already in the robot frame). */
	se2::Pose sensorPose{0, 0, 0};

	LandmarkKind kind() const { return key.kind; }
	int dim() const { return static_cast<int>(z.size()); }
};

}  // namespace vslam

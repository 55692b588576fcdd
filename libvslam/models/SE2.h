#pragma once
/** \file SE2.h
 * Planar pose algebra on mrpt::math::TPose2D (x, y, phi) with analytic
 * Jacobians. Small inline functions: they sit in the per-particle hot loop.
 * Every Jacobian is checked against a numerical derivative in SE2_unittest.
 */
#include <mrpt/math/TPose2D.h>
#include <mrpt/math/wrap2pi.h>

#include <Eigen/Core>
#include <cmath>

namespace vslam::se2
{
using Pose = mrpt::math::TPose2D;

/** Angle in (-pi, pi]; the common in-range case skips MRPT's fmod. */
inline double wrap(double a)
{
	if (a > -M_PI && a <= M_PI) return a;
	return mrpt::math::wrapToPi(a);
}

/** a (+) b: b expressed in the frame of a, mapped to the global frame. */
inline Pose compose(const Pose& a, const Pose& b)
{
	const double c = std::cos(a.phi), s = std::sin(a.phi);
	return {a.x + c * b.x - s * b.y, a.y + s * b.x + c * b.y, wrap(a.phi + b.phi)};
}

inline Pose inverse(const Pose& a)
{
	const double c = std::cos(a.phi), s = std::sin(a.phi);
	return {-c * a.x - s * a.y, s * a.x - c * a.y, wrap(-a.phi)};
}

/** b relative to a: inverse(a) (+) b, i.e. "where b is, seen from a". */
inline Pose between(const Pose& a, const Pose& b)
{
	const double c = std::cos(a.phi), s = std::sin(a.phi);
	const double dx = b.x - a.x, dy = b.y - a.y;
	return {c * dx + s * dy, -s * dx + c * dy, wrap(b.phi - a.phi)};
}

/** a - b as a 3-vector, with the angle difference wrapped to (-pi, pi]. */
inline Eigen::Vector3d difference(const Pose& a, const Pose& b)
{
	return {a.x - b.x, a.y - b.y, wrap(a.phi - b.phi)};
}

inline Eigen::Vector3d toVector(const Pose& p) { return {p.x, p.y, p.phi}; }
inline Pose fromVector(const Eigen::Vector3d& v) { return {v[0], v[1], wrap(v[2])}; }

/** d compose(a,b) / d a */
inline Eigen::Matrix3d jacComposeA(const Pose& a, const Pose& b)
{
	const double c = std::cos(a.phi), s = std::sin(a.phi);
	Eigen::Matrix3d J;
	J << 1, 0, -s * b.x - c * b.y,  //
		0, 1, c * b.x - s * b.y,  //
		0, 0, 1;
	return J;
}

/** d compose(a,b) / d b */
inline Eigen::Matrix3d jacComposeB(const Pose& a, const Pose& /*b*/)
{
	const double c = std::cos(a.phi), s = std::sin(a.phi);
	Eigen::Matrix3d J;
	J << c, -s, 0,  //
		s, c, 0,  //
		0, 0, 1;
	return J;
}

/** d between(a,b) / d a */
inline Eigen::Matrix3d jacBetweenA(const Pose& a, const Pose& b)
{
	const double c = std::cos(a.phi), s = std::sin(a.phi);
	const double dx = b.x - a.x, dy = b.y - a.y;
	Eigen::Matrix3d J;
	J << -c, -s, -s * dx + c * dy,  //
		s, -c, -c * dx - s * dy,  //
		0, 0, -1;
	return J;
}

/** d between(a,b) / d b */
inline Eigen::Matrix3d jacBetweenB(const Pose& a, const Pose& /*b*/)
{
	const double c = std::cos(a.phi), s = std::sin(a.phi);
	Eigen::Matrix3d J;
	J << c, s, 0,  //
		-s, c, 0,  //
		0, 0, 1;
	return J;
}

/** d inverse(a) / d a */
inline Eigen::Matrix3d jacInverse(const Pose& a)
{
	const double c = std::cos(a.phi), s = std::sin(a.phi);
	Eigen::Matrix3d J;
	J << -c, -s, s * a.x - c * a.y,  //
		s, -c, c * a.x + s * a.y,  //
		0, 0, -1;
	return J;
}

}  // namespace vslam::se2

#pragma once
/** \file NumericalDerivative.h
 * Central-difference Jacobians for checking analytic ones (GTSAM-style).
 * Output components listed in `angleRows` are differenced with wrapping. */
#include <libvslam/models/SE2.h>

#include <Eigen/Core>
#include <functional>
#include <set>

namespace vslam::testing
{
inline Eigen::MatrixXd numericalJacobian(
	const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& f,
	const Eigen::VectorXd& x, const std::set<int>& angleRows = {},
	double h = 1e-6)
{
	const Eigen::VectorXd f0 = f(x);
	Eigen::MatrixXd J(f0.size(), x.size());
	for (int j = 0; j < x.size(); j++)
	{
		Eigen::VectorXd xp = x, xm = x;
		xp[j] += h;
		xm[j] -= h;
		Eigen::VectorXd d = f(xp) - f(xm);
		for (int r : angleRows) d[r] = se2::wrap(d[r]);
		J.col(j) = d / (2 * h);
	}
	return J;
}

inline Eigen::VectorXd poseVec(const se2::Pose& p)
{
	Eigen::VectorXd v(3);
	v << p.x, p.y, p.phi;
	return v;
}

inline se2::Pose vecPose(const Eigen::VectorXd& v) { return {v[0], v[1], v[2]}; }

}  // namespace vslam::testing

#include <libvslam/frontend/StructureUncertainty.h>

#include <Eigen/Dense>

#include <cmath>
#include <limits>

namespace vslam
{
Eigen::Matrix<double, 2, 3> projectionJacobianWrtPoint(
	const Eigen::Matrix3d& R, const Eigen::Vector3d& t, double fx, double fy, const Eigen::Vector3d& X)
{
	const Eigen::Vector3d Xc = R * X + t;
	const double z = Xc.z(), z2 = z * z;
	Eigen::Matrix<double, 2, 3> Jproj;
	Jproj << fx / z, 0, -fx * Xc.x() / z2, 0, fy / z, -fy * Xc.y() / z2;
	return Jproj * R;
}

double stdAlongDirection(
	const std::vector<Eigen::Matrix<double, 2, 3>>& jacobians, const Eigen::Vector3d& direction, double sigmaPx)
{
	Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
	for (const auto& J : jacobians) information += J.transpose() * J;
	const Eigen::FullPivLU<Eigen::Matrix3d> lu(information);
	if (!lu.isInvertible()) return std::numeric_limits<double>::infinity();
	const Eigen::Vector3d u = direction.normalized();
	const double variance = sigmaPx * sigmaPx * u.dot(lu.solve(u));
	return variance > 0 ? std::sqrt(variance) : std::numeric_limits<double>::infinity();
}

bool poseCovariance(
	const std::vector<PoseSolveResidual>& residuals, double sigmaPx, Eigen::Matrix<double, 6, 6>& covariance)
{
	Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
	Eigen::Matrix<double, 6, 6> B = Eigen::Matrix<double, 6, 6>::Zero();
	const Eigen::Matrix2d pixelNoise = sigmaPx * sigmaPx * Eigen::Matrix2d::Identity();
	for (const auto& r : residuals)
	{
		A += r.jacobianWrtPose.transpose() * r.jacobianWrtPose;
		B += r.jacobianWrtPose.transpose() * (pixelNoise + r.structureCovariancePx) * r.jacobianWrtPose;
	}
	const Eigen::FullPivLU<Eigen::Matrix<double, 6, 6>> lu(A);
	if (!lu.isInvertible()) return false;
	const Eigen::Matrix<double, 6, 6> Ainv = lu.inverse();
	covariance = Ainv * B * Ainv;
	return true;
}
}  // namespace vslam

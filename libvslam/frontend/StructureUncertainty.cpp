#include <libvslam/frontend/StructureUncertainty.h>

#include <Eigen/Dense>
#include <opencv2/calib3d.hpp>

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

std::vector<PoseSolveResidual> poseSolveResiduals(const std::vector<cv::Point3f>& points,
	const std::vector<float>& relativeDepthStd, const Eigen::Vector3d& rayOrigin, const cv::Mat& rvec,
	const cv::Mat& tvec, const cv::Matx33d& K)
{
	cv::Mat jacobian;
	std::vector<cv::Point2f> projected;
	cv::projectPoints(points, rvec, tvec, cv::Mat(K), cv::noArray(), projected, jacobian);
	cv::Mat Rcv;
	cv::Rodrigues(rvec, Rcv);
	Eigen::Matrix3d R;
	for (int r = 0; r < 3; r++)
		for (int c = 0; c < 3; c++) R(r, c) = Rcv.at<double>(r, c);
	const Eigen::Vector3d t(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2));
	std::vector<PoseSolveResidual> residuals(points.size());
	for (size_t k = 0; k < points.size(); k++)
	{
		residuals[k].projectedPx = {projected[k].x, projected[k].y};
		for (int axis = 0; axis < 2; axis++)
			for (int c = 0; c < 6; c++)  // d/drvec (3), d/dtvec (3)
				residuals[k].jacobianWrtPose(axis, c) = jacobian.at<double>(static_cast<int>(2 * k) + axis, c);
		if (relativeDepthStd.empty()) continue;
		const Eigen::Vector3d X(points[k].x, points[k].y, points[k].z);
		const Eigen::Vector3d ray = X - rayOrigin;
		const Eigen::Vector2d alongRay =
			projectionJacobianWrtPoint(R, t, K(0, 0), K(1, 1), X) * ray.normalized() * (relativeDepthStd[k] * ray.norm());
		residuals[k].structureCovariancePx = alongRay * alongRay.transpose();
	}
	return residuals;
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

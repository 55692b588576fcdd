#include <libvslam/frontend/PlanarPose.h>

#include <Eigen/Dense>

#include <cmath>
#include <limits>

using namespace vslam;

namespace
{
constexpr double kMinDepth = 1e-6;
constexpr int kMaxRounds = 5;
constexpr int kMaxIterations = 20;

Eigen::Vector3d toEigen(const cv::Point3f& p) { return {p.x, p.y, p.z}; }

/** Squared reprojection error of point i, or infinity behind the camera. */
double squaredError(const PlanarCameraState& r, const cv::Point3f& point, const cv::Point2f& pixel,
	const mrpt::poses::CPose3D& mount, const cv::Matx33d& K)
{
	Eigen::Vector2d projected;
	if (!projectPlanar(r, toEigen(point), mount, K, projected)) return std::numeric_limits<double>::infinity();
	return (projected - Eigen::Vector2d(pixel.x, pixel.y)).squaredNorm();
}

std::vector<int> inliersOf(const PlanarCameraState& r, const std::vector<cv::Point3f>& points,
	const std::vector<cv::Point2f>& pixels, const mrpt::poses::CPose3D& mount, const cv::Matx33d& K,
	double inlierPx)
{
	std::vector<int> in;
	for (size_t i = 0; i < points.size(); i++)
		if (squaredError(r, points[i], pixels[i], mount, K) <= inlierPx * inlierPx) in.push_back(static_cast<int>(i));
	return in;
}

double cost(const PlanarCameraState& r, const std::vector<int>& use, const std::vector<cv::Point3f>& points,
	const std::vector<cv::Point2f>& pixels, const mrpt::poses::CPose3D& mount, const cv::Matx33d& K)
{
	double c = 0;
	for (int i : use) c += squaredError(r, points[i], pixels[i], mount, K);
	return c;
}

/** Levenberg-Marquardt on the points `use`. */
void levenbergMarquardt(PlanarCameraState& r, const std::vector<int>& use, const std::vector<cv::Point3f>& points,
	const std::vector<cv::Point2f>& pixels, const mrpt::poses::CPose3D& mount, const cv::Matx33d& K)
{
	double lambda = 1e-3, current = cost(r, use, points, pixels, mount, K);
	for (int it = 0; it < kMaxIterations; it++)
	{
		Eigen::Matrix4d H = Eigen::Matrix4d::Zero();
		Eigen::Vector4d g = Eigen::Vector4d::Zero();
		for (int i : use)
		{
			Eigen::Vector2d projected;
			Eigen::Matrix<double, 2, 4> J;
			if (!projectPlanar(r, toEigen(points[i]), mount, K, projected, &J)) continue;
			const Eigen::Vector2d e = projected - Eigen::Vector2d(pixels[i].x, pixels[i].y);
			H += J.transpose() * J;
			g += J.transpose() * e;
		}
		bool improved = false;
		while (lambda < 1e8)
		{
			Eigen::Matrix4d A = H;
			A.diagonal() *= 1 + lambda;
			const Eigen::Vector4d step = A.ldlt().solve(-g);
			const PlanarCameraState candidate{
				{r.robot.x + step[0], r.robot.y + step[1], se2::wrap(r.robot.phi + step[2])}, r.height + step[3]};
			const double c = cost(candidate, use, points, pixels, mount, K);
			if (c < current)
			{
				const bool converged = current - c < 1e-10 * (1 + current);
				r = candidate;
				current = c;
				lambda = std::max(1e-7, lambda / 10);
				improved = !converged;
				break;
			}
			lambda *= 10;
		}
		if (!improved) break;
	}
}
}  // namespace

bool vslam::projectPlanar(const PlanarCameraState& s, const Eigen::Vector3d& P, const mrpt::poses::CPose3D& mount,
	const cv::Matx33d& K, Eigen::Vector2d& pixel, Eigen::Matrix<double, 2, 4>* J)
{
	const se2::Pose& r = s.robot;
	const double c = std::cos(r.phi), sn = std::sin(r.phi);
	const Eigen::Vector3d d(P.x() - r.x, P.y() - r.y, P.z() - s.height);
	const Eigen::Vector3d Q(c * d.x() + sn * d.y(), -sn * d.x() + c * d.y(), d.z());  // in the robot frame
	const auto Rm = mount.getRotationMatrix();
	Eigen::Matrix3d RmT;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++) RmT(i, j) = Rm(j, i);
	const Eigen::Vector3d Pc = RmT * (Q - Eigen::Vector3d(mount.x(), mount.y(), mount.z()));
	if (Pc.z() < kMinDepth) return false;
	const double fx = K(0, 0), fy = K(1, 1), iz = 1 / Pc.z();
	pixel = {fx * Pc.x() * iz + K(0, 2), fy * Pc.y() * iz + K(1, 2)};
	if (J)
	{
		// dQ/dx = -R^T e_x, dQ/dy = -R^T e_y, dQ/dtheta = (Q_y, -Q_x, 0),
		// dQ/dheight = -e_z.
		Eigen::Matrix<double, 3, 4> dQ;
		dQ << -c, -sn, Q.y(), 0, sn, -c, -Q.x(), 0, 0, 0, 0, -1;
		Eigen::Matrix<double, 2, 3> dPixel;
		dPixel << fx * iz, 0, -fx * Pc.x() * iz * iz, 0, fy * iz, -fy * Pc.y() * iz * iz;
		*J = dPixel * RmT * dQ;
	}
	return true;
}

PlanarPoseFit vslam::refinePlanarPose(const PlanarCameraState& initial, const std::vector<int>& initialInliers,
	const std::vector<cv::Point3f>& points, const std::vector<cv::Point2f>& pixels,
	const mrpt::poses::CPose3D& mount, const cv::Matx33d& K, double inlierPx)
{
	PlanarPoseFit fit;
	fit.state = initial;
	fit.inliers = initialInliers;
	for (int round = 0; round < kMaxRounds && fit.inliers.size() >= 3; round++)
	{
		levenbergMarquardt(fit.state, fit.inliers, points, pixels, mount, K);
		auto again = inliersOf(fit.state, points, pixels, mount, K, inlierPx);
		const bool same = again == fit.inliers;
		fit.inliers = std::move(again);
		if (same) break;
	}
	if (fit.inliers.empty()) return fit;
	fit.rmsPx = std::sqrt(cost(fit.state, fit.inliers, points, pixels, mount, K) / static_cast<double>(fit.inliers.size()));
	// The information of the final inliers at the final pose.
	Eigen::Matrix4d H = Eigen::Matrix4d::Zero();
	for (int i : fit.inliers)
	{
		Eigen::Vector2d projected;
		Eigen::Matrix<double, 2, 4> J;
		if (projectPlanar(fit.state, toEigen(points[i]), mount, K, projected, &J)) H += J.transpose() * J;
	}
	// Per-coordinate pixel noise from the residuals (2 per inlier, 4
	// parameters fitted), at least 0.35 px.
	const double dof = std::max(1.0, 2.0 * fit.inliers.size() - 4);
	const double squaredResiduals = static_cast<double>(fit.inliers.size()) * fit.rmsPx * fit.rmsPx;
	const double sigma = std::max(0.35, std::sqrt(squaredResiduals / dof));
	Eigen::FullPivLU<Eigen::Matrix4d> lu(H);
	fit.covariance = lu.isInvertible()
		? Eigen::Matrix3d((sigma * sigma * lu.inverse()).topLeftCorner<3, 3>())
		: Eigen::Matrix3d::Constant(std::numeric_limits<double>::infinity());
	return fit;
}

#include <libvslam/frontend/InlierSpread.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

double vslam::inlierMinorSpread(const std::vector<cv::Point2f>& pixels, const cv::Matx33d& K)
{
	if (pixels.size() < 2) return 0;
	Eigen::Vector2d mean = Eigen::Vector2d::Zero();
	std::vector<Eigen::Vector2d> rays;
	rays.reserve(pixels.size());
	for (const cv::Point2f& p : pixels)
	{
		rays.emplace_back((p.x - K(0, 2)) / K(0, 0), (p.y - K(1, 2)) / K(1, 1));
		mean += rays.back();
	}
	mean /= static_cast<double>(rays.size());
	Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
	for (const Eigen::Vector2d& r : rays) cov += (r - mean) * (r - mean).transpose();
	cov /= static_cast<double>(rays.size());
	const double least = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(cov, Eigen::EigenvaluesOnly).eigenvalues()[0];
	return std::sqrt(std::max(0.0, least));
}

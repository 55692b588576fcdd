#include <libvslam/frontend/InlierSpread.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

double vslam::inlierMinorSpread(const std::vector<cv::Point2f>& pixels, const cv::Matx33d& K)
{
	if (pixels.size() < 2) return 0;
	Eigen::Vector2d sum = Eigen::Vector2d::Zero();
	Eigen::Matrix2d sumOfSquares = Eigen::Matrix2d::Zero();
	for (const cv::Point2f& p : pixels)
	{
		const Eigen::Vector2d ray((p.x - K(0, 2)) / K(0, 0), (p.y - K(1, 2)) / K(1, 1));
		sum += ray;
		sumOfSquares += ray * ray.transpose();
	}
	const double n = static_cast<double>(pixels.size());
	const Eigen::Matrix2d cov = sumOfSquares / n - (sum / n) * (sum / n).transpose();
	const double least = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(cov, Eigen::EigenvaluesOnly).eigenvalues()[0];
	return std::sqrt(std::max(0.0, least));
}

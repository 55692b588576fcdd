#include <libvslam/frontend/StructureUncertainty.h>
#include <libvslam/frontend/WeightedPoseRefinement.h>

#include <Eigen/Dense>
#include <opencv2/calib3d.hpp>

#include <algorithm>
#include <cmath>

namespace vslam
{
namespace
{
/** The whitened normal equations of one pose: H = sum J^T W^-1 J,
 * g = sum J^T W^-1 r, and the cost sum r^T W^-1 r. */
struct NormalEquations
{
	Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();
	Eigen::Matrix<double, 6, 1> g = Eigen::Matrix<double, 6, 1>::Zero();
	double cost = 0;
};

std::vector<Eigen::Vector2d> reprojectionErrors(const std::vector<cv::Point3f>& points,
	const std::vector<cv::Point2f>& pixels, const cv::Matx33d& K, const cv::Mat& rvec, const cv::Mat& tvec)
{
	std::vector<cv::Point2f> projected;
	cv::projectPoints(points, rvec, tvec, cv::Mat(K), cv::noArray(), projected);
	std::vector<Eigen::Vector2d> r(points.size());
	for (size_t k = 0; k < points.size(); k++)
		r[k] = {projected[k].x - pixels[k].x, projected[k].y - pixels[k].y};
	return r;
}

/** The reprojection errors at the pose the residuals were taken at. */
std::vector<Eigen::Vector2d> reprojectionErrors(
	const std::vector<PoseSolveResidual>& residuals, const std::vector<cv::Point2f>& pixels)
{
	std::vector<Eigen::Vector2d> r(residuals.size());
	for (size_t k = 0; k < residuals.size(); k++)
		r[k] = residuals[k].projectedPx - Eigen::Vector2d(pixels[k].x, pixels[k].y);
	return r;
}

/** The weights' inverses (sigma^2 I + structure) at one pose, held fixed
 * while a step is taken and judged. */
std::vector<Eigen::Matrix2d> inverseWeights(const std::vector<PoseSolveResidual>& residuals, double sigmaPx)
{
	std::vector<Eigen::Matrix2d> out;
	out.reserve(residuals.size());
	for (const auto& r : residuals)
		out.push_back((sigmaPx * sigmaPx * Eigen::Matrix2d::Identity() + r.structureCovariancePx).inverse());
	return out;
}

double costOf(const std::vector<Eigen::Vector2d>& errors, const std::vector<Eigen::Matrix2d>& information)
{
	double cost = 0;
	for (size_t k = 0; k < errors.size(); k++) cost += errors[k].dot(information[k] * errors[k]);
	return cost;
}

NormalEquations normalEquations(const std::vector<PoseSolveResidual>& residuals,
	const std::vector<Eigen::Vector2d>& errors, const std::vector<Eigen::Matrix2d>& information)
{
	NormalEquations n;
	for (size_t k = 0; k < residuals.size(); k++)
	{
		const Eigen::Matrix<double, 6, 2> JtW = residuals[k].jacobianWrtPose.transpose() * information[k];
		n.H += JtW * residuals[k].jacobianWrtPose;
		n.g += JtW * errors[k];
	}
	n.cost = costOf(errors, information);
	return n;
}
}  // namespace

bool refinePoseWeightedByStructure(const std::vector<cv::Point3f>& points, const std::vector<cv::Point2f>& pixels,
	const std::vector<float>& relativeDepthStd, const Eigen::Vector3d& rayOrigin, const cv::Matx33d& K,
	double sigmaPx, cv::Mat& rvec, cv::Mat& tvec, Eigen::Matrix<double, 6, 6>& covariance)
{
	constexpr size_t kLeastPoints = 4;
	constexpr int kMaxSteps = 10;
	constexpr double kConverged = 1e-9;  // relative cost decrease
	if (points.size() < kLeastPoints || pixels.size() != points.size()) return false;
	cv::Mat r = rvec.clone(), t = tvec.clone();
	for (int step = 0; step < kMaxSteps; step++)
	{
		const auto residuals = poseSolveResiduals(points, relativeDepthStd, rayOrigin, r, t, K);
		const auto information = inverseWeights(residuals, sigmaPx);
		const NormalEquations n =
			normalEquations(residuals, reprojectionErrors(residuals, pixels), information);
		const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(n.H);
		if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-12)) return false;
		const Eigen::Matrix<double, 6, 1> delta = -ldlt.solve(n.g);
		// Halve a step that does not lower the cost (the weights held).
		bool lowered = false;
		for (double scale = 1; scale > 1.0 / 64 && !lowered; scale /= 2)
		{
			cv::Mat rTry = r.clone(), tTry = t.clone();
			for (int i = 0; i < 3; i++)
			{
				rTry.at<double>(i) += scale * delta(i);
				tTry.at<double>(i) += scale * delta(3 + i);
			}
			const double tried = costOf(reprojectionErrors(points, pixels, K, rTry, tTry), information);
			if (tried < n.cost)
			{
				lowered = true;
				r = rTry;
				t = tTry;
				if (n.cost - tried <= kConverged * n.cost) step = kMaxSteps;
			}
		}
		if (!lowered) break;
	}
	const auto residuals = poseSolveResiduals(points, relativeDepthStd, rayOrigin, r, t, K);
	const NormalEquations n =
		normalEquations(residuals, reprojectionErrors(residuals, pixels), inverseWeights(residuals, sigmaPx));
	const Eigen::FullPivLU<Eigen::Matrix<double, 6, 6>> lu(n.H);
	if (!lu.isInvertible()) return false;
	const double dof = 2.0 * static_cast<double>(points.size()) - 6;
	const double reducedChiSquare = dof > 0 ? n.cost / dof : 1;
	covariance = lu.inverse() * std::max(1.0, reducedChiSquare);
	rvec = r;
	tvec = t;
	return true;
}
}  // namespace vslam

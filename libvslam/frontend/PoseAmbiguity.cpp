#include <libvslam/frontend/PoseAmbiguity.h>

#include <opencv2/calib3d.hpp>

#include <algorithm>
#include <cmath>

using namespace vslam;

namespace
{
cv::Matx33d rotation(const cv::Vec3d& rvec)
{
	cv::Matx33d R;
	cv::Rodrigues(rvec, R);
	return R;
}

cv::Vec3d cameraCentre(const CameraPoseFit& p) { return -(rotation(p.rvec).t() * p.tvec); }

/** Mean depth of the points in front of the camera, or a negative value
 * if any is behind it. */
double meanDepth(const std::vector<cv::Point3f>& object, const CameraPoseFit& p)
{
	const cv::Matx33d R = rotation(p.rvec);
	double sum = 0;
	for (const auto& X : object)
	{
		const double z = (R * cv::Vec3d(X.x, X.y, X.z) + p.tvec)[2];
		if (z <= 0) return -1;
		sum += z;
	}
	return sum / static_cast<double>(object.size());
}

double rmsReprojection(const std::vector<cv::Point3f>& object, const std::vector<cv::Point2f>& pixels,
	const cv::Matx33d& K, const CameraPoseFit& p)
{
	std::vector<cv::Point2f> projected;
	cv::projectPoints(object, p.rvec, p.tvec, K, cv::noArray(), projected);
	double sq = 0;
	for (size_t i = 0; i < object.size(); i++)
		sq += std::pow(projected[i].x - pixels[i].x, 2) + std::pow(projected[i].y - pixels[i].y, 2);
	return std::sqrt(sq / static_cast<double>(object.size()));
}

/** The points projected onto their least-squares plane: IPPE takes only
 * coplanar points, and the seeds it gives are refined on the real ones. */
std::vector<cv::Point3f> flattened(const std::vector<cv::Point3f>& object)
{
	cv::Mat data(static_cast<int>(object.size()), 3, CV_64F);
	for (int i = 0; i < data.rows; i++)
	{
		data.at<double>(i, 0) = object[i].x;
		data.at<double>(i, 1) = object[i].y;
		data.at<double>(i, 2) = object[i].z;
	}
	const cv::PCA pca(data, cv::noArray(), cv::PCA::DATA_AS_ROW);
	const cv::Vec3d mean(pca.mean), normal(pca.eigenvectors.row(2));
	std::vector<cv::Point3f> flat;
	for (const auto& X : object)
	{
		const cv::Vec3d p(X.x, X.y, X.z);
		const cv::Vec3d q = p - (p - mean).dot(normal) * normal;
		flat.emplace_back(static_cast<float>(q[0]), static_cast<float>(q[1]), static_cast<float>(q[2]));
	}
	return flat;
}

bool samePose(const CameraPoseFit& a, const CameraPoseFit& b, double depth, const SamePoseTolerance& tol)
{
	cv::Vec3d relative;
	cv::Rodrigues(rotation(a.rvec).t() * rotation(b.rvec), relative);
	return cv::norm(relative) < tol.rotationRad &&
		cv::norm(cameraCentre(a) - cameraCentre(b)) < tol.centreShareOfDepth * depth;
}
}  // namespace

std::optional<CameraPoseFit> vslam::competingPose(const std::vector<cv::Point3f>& object,
	const std::vector<cv::Point2f>& pixels, const cv::Matx33d& K, const CameraPoseFit& pose,
	const SamePoseTolerance& same)
{
	if (object.size() < 4 || object.size() != pixels.size()) return std::nullopt;
	const double depth = meanDepth(object, pose);
	if (depth <= 0) return std::nullopt;
	std::vector<cv::Mat> rvecs, tvecs;
	try
	{
		cv::solvePnPGeneric(flattened(object), pixels, K, cv::noArray(), rvecs, tvecs, false, cv::SOLVEPNP_IPPE);
	}
	catch (const cv::Exception&)
	{
		return std::nullopt;  // degenerate points (e.g. collinear): no plane
	}
	std::optional<CameraPoseFit> best;
	for (size_t k = 0; k < rvecs.size(); k++)
	{
		cv::Mat rvec = rvecs[k].clone(), tvec = tvecs[k].clone();
		cv::solvePnPRefineLM(object, pixels, K, cv::noArray(), rvec, tvec);
		CameraPoseFit fit{cv::Vec3d(rvec), cv::Vec3d(tvec), 0};
		if (!std::isfinite(cv::norm(fit.rvec)) || !std::isfinite(cv::norm(fit.tvec))) continue;
		if (meanDepth(object, fit) <= 0 || samePose(fit, pose, depth, same)) continue;
		fit.rmsPx = rmsReprojection(object, pixels, K, fit);
		if (!best || fit.rmsPx < best->rmsPx) best = fit;
	}
	return best;
}

double vslam::reprojectionCostGap(const CameraPoseFit& pose, const CameraPoseFit& competitor, size_t n, double floorPx)
{
	const double sigma = std::max(floorPx, pose.rmsPx);
	return static_cast<double>(n) * (competitor.rmsPx * competitor.rmsPx - pose.rmsPx * pose.rmsPx) / (sigma * sigma);
}

#include <libvslam/config/StrictRead.h>
#include <libvslam/frontend/DescriptorCodec.h>
#include <libvslam/frontend/DescriptorMatching.h>
#include <libvslam/frontend/LandmarkRecognizer.h>
#include <libvslam/frontend/RansacIterations.h>
#include <libvslam/frontend/StructureUncertainty.h>
#include <libvslam/frontend/WeightedPoseRefinement.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/wrap2pi.h>

#include <Eigen/Dense>
#include <opencv2/calib3d.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

using namespace vslam;

namespace
{
/** The measurement (landmark in the robot frame, robot in the landmark
 * frame, Slope) of a PnP solution X_cam = R(rvec) X_landmark + tvec. */
VisualMeasurement measurementFromPnP(const cv::Mat& rvec, const cv::Mat& tvec, const mrpt::poses::CPose3D& mount)
{
	cv::Mat Rcv;
	cv::Rodrigues(rvec, Rcv);
	mrpt::math::CMatrixDouble44 T = mrpt::math::CMatrixDouble44::Identity();
	for (int r = 0; r < 3; r++)
	{
		for (int c = 0; c < 3; c++) T(r, c) = Rcv.at<double>(r, c);
		T(r, 3) = tvec.at<double>(r);
	}
	const mrpt::poses::CPose3D landmarkToCamera(T);
	const mrpt::poses::CPose3D cameraInLandmark = mrpt::poses::CPose3D() - landmarkToCamera;
	VisualMeasurement m;
	m.robotInLandmark = cameraInLandmark + (mrpt::poses::CPose3D() - mount);
	const auto Rr = m.robotInLandmark.getRotationMatrix();
	m.Slope = std::acos(std::clamp(Rr(2, 2), -1.0, 1.0));
	m.tilt = {Rr(0, 2), Rr(1, 2)};
	const mrpt::poses::CPose2D robotPlanar(m.robotInLandmark.x(), m.robotInLandmark.y(), m.robotInLandmark.yaw());
	m.landmarkInRobot = mrpt::poses::CPose2D() - robotPlanar;
	return m;
}

/** Sets the predicted covariance of `m`'s (dx, dy, dtheta), and the
 * position and heading std from it. */
void setPredictedCovariance(VisualMeasurement& m, const Eigen::Matrix3d& cov)
{
	m.covariance = cov;
	m.stdPosition = std::sqrt(std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(cov.topLeftCorner<2, 2>())
												 .eigenvalues()
												 .maxCoeff()));
	m.stdHeading = std::sqrt(std::max(0.0, cov(2, 2)));
}

/** The predicted std of Slope = |tilt| from the tilt's 2x2 covariance:
 * along the tilt's direction, or where the tilt is nearly zero (and its
 * direction undefined) along the most uncertain one. */
double slopeStd(const Eigen::Vector2d& tilt, const Eigen::Matrix2d& cov)
{
	if (tilt.norm() < 1e-9)
		return std::sqrt(std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(cov).eigenvalues().maxCoeff()));
	const Eigen::Vector2d u = tilt.normalized();
	return std::sqrt(std::max(0.0, u.dot(cov * u)));
}

constexpr double kRansacConfidence = 0.999;
/** A consensus threshold that counts every match. */
constexpr double kNoThreshold = std::numeric_limits<double>::infinity();
/** AP3P draws 4 points. */
constexpr int kRansacSampleSize = 4;

/** RANSAC draws for `matches` 2-D/3-D matches: ransac_iterations
 * at most, and no more than a pose with min_inliers would take
 * to be drawn with kRansacConfidence (RansacIterations.h): a candidate
 * without one then costs a fraction of the budget. */
int ransacDraws(int matches, const CLandmarkRecognizer::TOptions& o)
{
	if (matches < kRansacSampleSize) return o.ransac_iterations;
	return std::min(o.ransac_iterations,
		ransacIterationsToFind(o.min_inliers, matches, kRansacSampleSize, kRansacConfidence));
}

/** RANSAC PnP (OpenCV's solvePnPRansac, AP3P minimal sets); true if a pose was found. */
bool robustPnP(const std::vector<cv::Point3f>& object, const std::vector<cv::Point2f>& pixels, const cv::Mat& K,
	const CLandmarkRecognizer::TOptions& o, cv::Mat& rvec, cv::Mat& tvec, std::vector<int>& inliers)
{
	const int iterations = ransacDraws(static_cast<int>(object.size()), o);
	return cv::solvePnPRansac(object, pixels, K, cv::noArray(), rvec, tvec, false, iterations,
		static_cast<float>(o.ransac_px), kRansacConfidence, inliers, cv::SOLVEPNP_AP3P);
}

/** The elements of `all` at `rows`, in that order. */
template <typename T>
std::vector<T> subset(const std::vector<T>& all, const std::vector<int>& rows)
{
	std::vector<T> out;
	out.reserve(rows.size());
	for (int i : rows) out.push_back(all[i]);
	return out;
}

/** The matches a pose reprojects within ransac_px, and the sum
 * of their squared errors. */
struct PoseConsensus
{
	std::vector<int> inliers;
	double sumSquaredPx = 0;
};

PoseConsensus consensusOf(const std::vector<cv::Point3f>& object, const std::vector<cv::Point2f>& pixels,
	const cv::Mat& K, const cv::Mat& rvec, const cv::Mat& tvec, double thresholdPx)
{
	std::vector<cv::Point2f> projected;
	cv::projectPoints(object, rvec, tvec, K, cv::noArray(), projected);
	PoseConsensus c;
	for (size_t i = 0; i < object.size(); i++)
	{
		const double e2 = std::pow(projected[i].x - pixels[i].x, 2) + std::pow(projected[i].y - pixels[i].y, 2);
		if (e2 <= thresholdPx * thresholdPx)
		{
			c.sumSquaredPx += e2;
			c.inliers.push_back(static_cast<int>(i));
		}
	}
	return c;
}

/** Refines RANSAC's pose (rvec, tvec) on its inliers and counts the inliers
 * again among all matches. */
PoseConsensus refineOnInliers(const std::vector<cv::Point3f>& object, const std::vector<cv::Point2f>& pixels,
	const cv::Mat& K, double inlierPx, const std::vector<int>& ransacInliers, cv::Mat& rvec, cv::Mat& tvec)
{
	cv::solvePnPRefineLM(subset(object, ransacInliers), subset(pixels, ransacInliers), K, cv::noArray(), rvec, tvec);
	return consensusOf(object, pixels, K, rvec, tvec, inlierPx);
}

/** The 2-D/3-D matches a recognition is solved from: for each, the 3-D
 * point, the pixel, and the row of the landmark point it comes from. */
struct Correspondences
{
	std::vector<cv::Point3f> object;
	std::vector<cv::Point2f> pixels;
	std::vector<int> point;

	void add(const VisualLandmarkModel& lm, const ImageFeatures& image, int featureRow, int pointRow)
	{
		object.push_back(lm.points[pointRow]);
		pixels.push_back(image.pixels[featureRow]);
		point.push_back(pointRow);
	}
	size_t size() const { return object.size(); }
};

/** How the measurement moves with the PnP pose, by central differences. */
struct MeasurementJacobians
{
	Eigen::Matrix<double, 3, 6> F;  //!< d(dx, dy, dtheta) / d(rvec, tvec)
	Eigen::Matrix<double, 2, 6> G;  //!< d tilt / d(rvec, tvec)
};

MeasurementJacobians measurementJacobians(const cv::Mat& rvec, const cv::Mat& tvec, const mrpt::poses::CPose3D& mount)
{
	MeasurementJacobians J;
	for (int k = 0; k < 6; k++)
	{
		constexpr double h = 1e-6;
		cv::Mat rp = rvec.clone(), tp = tvec.clone(), rm = rvec.clone(), tm = tvec.clone();
		(k < 3 ? rp : tp).at<double>(k % 3) += h;
		(k < 3 ? rm : tm).at<double>(k % 3) -= h;
		const VisualMeasurement plus = measurementFromPnP(rp, tp, mount);
		const VisualMeasurement minus = measurementFromPnP(rm, tm, mount);
		const auto& a = plus.landmarkInRobot;
		const auto& b = minus.landmarkInRobot;
		J.F(0, k) = (a.x() - b.x()) / (2 * h);
		J.F(1, k) = (a.y() - b.y()) / (2 * h);
		J.F(2, k) = mrpt::math::wrapToPi(a.phi() - b.phi()) / (2 * h);
		J.G.col(k) = (plus.tilt - minus.tilt) / (2 * h);
	}
	return J;
}
}  // namespace

std::optional<VisualMeasurement> CLandmarkRecognizer::recognize(
	const ImageFeatures& image, const VisualLandmarkModel& lm, const mrpt::poses::CPose3D& mount) const
{
	const TOptions& o = m_options;
	const cv::Mat& query = image.codes.empty() ? image.descriptors : image.codes;
	const cv::Mat landmarkDescriptors = DescriptorCodec::decode(lm.descriptors);
	const auto matches = matchDescriptors(query, landmarkDescriptors, m_matchRatio);
	if (static_cast<int>(matches.size()) < o.min_inliers) return std::nullopt;
	Correspondences c;
	for (const auto& [qi, pi] : matches) c.add(lm, image, qi, pi);
	const cv::Mat K(image.camera.K());
	cv::Mat rvec, tvec;
	std::vector<int> inliers;
	const bool found = robustPnP(c.object, c.pixels, K, o, rvec, tvec, inliers);
	if (!found || static_cast<int>(inliers.size()) < o.min_inliers) return std::nullopt;
	PoseConsensus fit = refineOnInliers(c.object, c.pixels, K, o.ransac_px, inliers, rvec, tvec);
	if (static_cast<int>(fit.inliers.size()) < o.min_inliers) return std::nullopt;
	const std::vector<cv::Point3f>& object = c.object;
	const std::vector<cv::Point2f>& pixels = c.pixels;
	const std::vector<int>& refinedInliers = fit.inliers;
	const int n = static_cast<int>(refinedInliers.size());
	const std::vector<cv::Point3f> inlierObject = subset(object, refinedInliers);
	const std::vector<cv::Point2f> inlierPixels = subset(pixels, refinedInliers);
	std::vector<float> inlierDepthStd;  // empty: the points taken as exact
	if (o.structure_weighted && lm.depthStd.size() == lm.points.size())
		for (int i : refinedInliers) inlierDepthStd.push_back(lm.depthStd[c.point[i]]);
	// The landmark was built by this camera on this mount.
	const Eigen::Vector3d creationCamera(mount.x(), mount.y(), mount.z());

	// Predicted uncertainty: the pose covariance of the least-squares fit
	// over the inliers, carried to (dx, dy, dtheta) and to the tilt by a
	// numerical Jacobian. With structure_weighted, the fit
	// weighted by each point's depth uncertainty, and its covariance;
	// otherwise the unweighted fit's (pixel noise sigma: their RMS error, at
	// least kLeastPixelNoisePx).
	Eigen::Matrix<double, 6, 6> poseCov;
	bool conditioned = o.structure_weighted && !inlierDepthStd.empty() &&
		refinePoseWeightedByStructure(inlierObject, inlierPixels, inlierDepthStd, creationCamera, image.camera.K(),
			kLeastPixelNoisePx, rvec, tvec, poseCov);
	if (conditioned) fit.sumSquaredPx = consensusOf(inlierObject, inlierPixels, K, rvec, tvec, kNoThreshold).sumSquaredPx;

	VisualMeasurement m = measurementFromPnP(rvec, tvec, mount);
	m.landmarkID = lm.id;
	m.NPoints = n;
	m.ProjErrRMS = std::sqrt(fit.sumSquaredPx / n);
	m.matches = static_cast<int>(c.size());
	if (!conditioned)
		conditioned = poseCovariance(
			poseSolveResiduals(inlierObject, std::vector<float>(), creationCamera, rvec, tvec, image.camera.K()),
			std::max(kLeastPixelNoisePx, m.ProjErrRMS), poseCov);
	if (!conditioned)
	{
		m.stdSlope = m.stdPosition = m.stdHeading = std::numeric_limits<double>::infinity();
		m.covariance.setConstant(std::numeric_limits<double>::infinity());
		return m;
	}
	const MeasurementJacobians J = measurementJacobians(rvec, tvec, mount);
	m.stdSlope = slopeStd(m.tilt, J.G * poseCov * J.G.transpose());
	setPredictedCovariance(m, J.F * poseCov * J.F.transpose());
	return m;
}

void CLandmarkRecognizer::TOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace config;
	min_inliers = readCount(c, s, "min_inliers", min_inliers, 6, 100000);
	ransac_px = readDouble(c, s, "ransac_px", ransac_px, Range::positive());
	ransac_iterations = readCount(c, s, "ransac_iterations", ransac_iterations, 1, 100000);
	structure_weighted = readBool(c, s, "structure_weighted", structure_weighted);
	odometry_gate.horizon = readDouble(c, s, "odometry_gate_s", odometry_gate.horizon, Range::nonNegative());
}

void CLandmarkRecognizer::TOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "min_inliers", min_inliers, 30, 10, "PnP inliers needed to accept a pose");
	c.write(s, "ransac_px", ransac_px, 30, 10, "RANSAC inlier threshold [px]");
	c.write(s, "ransac_iterations", ransac_iterations, 30, 10, "RANSAC draw budget");
	c.write(s, "structure_weighted", structure_weighted, 30, 10,
		"Refine the pose weighting each inlier by its pixel noise plus its point's depth uncertainty from creation (6-DOF solve)");
	c.write(s, "odometry_gate_s", odometry_gate.horizon, 30, 10,
		"Reject a pose that disagrees with the landmark's last kept one at most this old, carried by the odometry (by 0.3 m + 10% of its distance, or 10 deg) [s] (0: off)");
}

#include <libvslam/frontend/DescriptorCodec.h>
#include <libvslam/frontend/LandmarkRecognizer.h>
#include <mrpt/math/CMatrixFixed.h>
#include <opencv2/calib3d.hpp>

#include <algorithm>
#include <cmath>

using namespace vslam;


std::optional<VisualMeasurement> vslam::recognizeLandmark(
	const ImageFeatures& image, const VisualLandmarkModel& lm, const mrpt::poses::CPose3D& mount,
	const TVisualFrontEndOptions& o)
{
	const cv::Mat& query = image.codes.empty() ? image.descriptors : image.codes;
	const auto matches = matchDescriptors(query, DescriptorCodec::decode(lm.descriptors), o.match_ratio);
	if (static_cast<int>(matches.size()) < o.recognition_min_inliers) return std::nullopt;
	std::vector<cv::Point3f> object;
	std::vector<cv::Point2f> pixels;
	for (const auto& [qi, pi] : matches)
	{
		object.push_back(lm.points[pi]);
		pixels.push_back(image.pixels[qi]);
	}
	const cv::Mat K(image.camera.K());
	cv::Mat rvec, tvec;
	std::vector<int> inliers;
	const bool found = cv::solvePnPRansac(object, pixels, K, cv::noArray(), rvec, tvec, false,
		o.recognition_ransac_iterations, static_cast<float>(o.recognition_ransac_px), 0.999, inliers,
		cv::SOLVEPNP_AP3P);
	if (!found || static_cast<int>(inliers.size()) < o.recognition_min_inliers) return std::nullopt;
	std::vector<cv::Point3f> inObject;
	std::vector<cv::Point2f> inPixels;
	for (int i : inliers)
	{
		inObject.push_back(object[i]);
		inPixels.push_back(pixels[i]);
	}
	cv::solvePnPRefineLM(inObject, inPixels, K, cv::noArray(), rvec, tvec);
	// Inliers again after the refinement, and their RMS error.
	std::vector<cv::Point2f> projected;
	cv::projectPoints(object, rvec, tvec, K, cv::noArray(), projected);
	double sq = 0;
	int n = 0;
	for (size_t i = 0; i < object.size(); i++)
	{
		const double e2 = std::pow(projected[i].x - pixels[i].x, 2) + std::pow(projected[i].y - pixels[i].y, 2);
		if (e2 <= o.recognition_ransac_px * o.recognition_ransac_px)
		{
			sq += e2;
			n++;
		}
	}
	if (n < o.recognition_min_inliers) return std::nullopt;

	// X_cam = R X_landmark + t  ->  camera in the landmark frame -> robot.
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
	m.landmarkID = lm.id;
	m.robotInLandmark = cameraInLandmark + (mrpt::poses::CPose3D() - mount);
	const auto Rr = m.robotInLandmark.getRotationMatrix();
	m.Slope = std::acos(std::clamp(Rr(2, 2), -1.0, 1.0));
	const mrpt::poses::CPose2D robotPlanar(m.robotInLandmark.x(), m.robotInLandmark.y(), m.robotInLandmark.yaw());
	m.landmarkInRobot = mrpt::poses::CPose2D() - robotPlanar;
	m.NPoints = n;
	m.ProjErrRMS = std::sqrt(sq / n);
	m.matches = static_cast<int>(matches.size());
	return m;
}

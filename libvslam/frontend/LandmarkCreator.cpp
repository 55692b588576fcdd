#include <libvslam/config/ConfigError.h>
#include <libvslam/config/StrictRead.h>
#include <libvslam/frontend/BundleAdjustment.h>
#include <libvslam/frontend/DescriptorMatching.h>
#include <libvslam/frontend/LandmarkCreator.h>
#include <libvslam/frontend/StructureUncertainty.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>

using namespace vslam;

namespace
{
/** X_v = R X_last + t: the pose of view v relative to the newest camera. */
ba::CameraPose relativePose(const mrpt::poses::CPose3D& cameraV, const mrpt::poses::CPose3D& cameraLast)
{
	const mrpt::poses::CPose3D rel = cameraLast - cameraV;  // cameraV^-1 (+) cameraLast: last -> v
	ba::CameraPose p;
	p.R = rel.getRotationMatrix().asEigen();
	p.t = Eigen::Vector3d(rel.x(), rel.y(), rel.z());
	return p;
}

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
	return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
}

/** Each point's std along its ray from camera 0 (the newest), relative to
 * its distance, with the cameras fixed at their refined poses and pixel
 * noise sigmaPx (StructureUncertainty.h). */
std::vector<float> relativeDepthStds(const ba::Problem& problem, double sigmaPx)
{
	std::vector<std::vector<Eigen::Matrix<double, 2, 3>>> jacobians(problem.points.size());
	for (const auto& ob : problem.observations)
	{
		Eigen::Matrix<double, 2, 6> Jcam;
		Eigen::Matrix<double, 2, 3> Jpoint;
		ba::jacobians(problem, ob, Jcam, Jpoint);
		jacobians[ob.point].push_back(Jpoint);
	}
	std::vector<float> out;
	out.reserve(problem.points.size());
	for (size_t i = 0; i < problem.points.size(); i++)
	{
		const Eigen::Vector3d& X = problem.points[i];  // camera 0 is at the origin
		const double relative = stdAlongDirection(jacobians[i], X, sigmaPx) / X.norm();
		out.push_back(static_cast<float>(std::min(relative, static_cast<double>(std::numeric_limits<float>::max()))));
	}
	return out;
}

/** The pixel noise of a refined problem: the RMS residual of the points
 * whose worst residual (`worstOfPoint`) is within `maxPx`, at least
 * kLeastPixelNoisePx. */
double pixelNoiseOf(const ba::Problem& problem, const std::vector<double>& worstOfPoint, double maxPx)
{
	double sq = 0;
	size_t count = 0;
	for (const auto& ob : problem.observations)
		if (worstOfPoint[ob.point] <= maxPx)
		{
			sq += ba::residual(problem, ob).squaredNorm();
			count++;
		}
	return std::max(kLeastPixelNoisePx, count ? std::sqrt(sq / count) : 0.0);
}

double rotationAngle(const Eigen::Matrix3d& R)
{
	return std::acos(std::clamp((R.trace() - 1) / 2, -1.0, 1.0));
}

/** The essential matrix between the newest and the oldest view: a better
 * relative rotation than odometry's, and the baseline direction; used
 * only when it agrees with odometry (a wrong solution is worse than none). */
bool poseFromImages(
	const PinholeCamera& cam, const std::vector<cv::Point2f>& last, const std::vector<cv::Point2f>& oldest,
	const ba::CameraPose& odometry, ba::CameraPose& out, std::vector<bool>& inlier)
{
	const double baseline = odometry.t.norm();
	if (baseline <= 0 || last.size() < 8) return false;
	cv::Mat inliers;
	const cv::Mat K(cam.K());
	const cv::Mat E = cv::findEssentialMat(last, oldest, K, cv::RANSAC, 0.999, 1.0, inliers);
	if (E.rows != 3 || E.cols != 3) return false;
	cv::Mat R, t;
	const int good = cv::recoverPose(E, last, oldest, K, R, t, inliers);
	if (good < 8) return false;
	ba::CameraPose p;
	cv::cv2eigen(R, p.R);
	Eigen::Vector3d dir;
	cv::cv2eigen(t, dir);
	p.t = dir.normalized() * baseline;
	constexpr double kMaxDirectionError = 30 * M_PI / 180, kMaxRotationError = 10 * M_PI / 180;
	if (angleBetween(p.t, odometry.t) > kMaxDirectionError) return false;
	if (rotationAngle(p.R * odometry.R.transpose()) > kMaxRotationError) return false;
	out = p;
	inlier.assign(last.size(), false);
	for (int i = 0; i < inliers.rows; i++) inlier[i] = inliers.at<uchar>(i) != 0;
	return true;
}
/** Tracks: features of the newest view matched in every other view; each
 * is [feature in the newest, in view 0, ..., in view n-2]. */
std::vector<std::vector<int>> matchTracks(const std::vector<const CreationView*>& views, double matchRatio)
{
	const int n = static_cast<int>(views.size());
	const CreationView& last = *views.back();
	std::vector<std::map<int, int>> matchOf(n - 1);
	for (int v = 0; v + 1 < n; v++)
		for (const auto& [a, b] : matchDescriptors(last.features.descriptors, views[v]->features.descriptors, matchRatio))
			matchOf[v][a] = b;
	std::vector<std::vector<int>> tracks;
	for (const auto& [a, b0] : matchOf[0])
	{
		std::vector<int> t{a, b0};
		for (int v = 1; v + 1 < n; v++)
		{
			const auto it = matchOf[v].find(a);
			if (it == matchOf[v].end()) break;
			t.push_back(it->second);
		}
		if (static_cast<int>(t.size()) == n) tracks.push_back(std::move(t));
	}
	return tracks;
}

/** The bundle adjustment problem's cameras relative to the newest, from
 * odometry, with odometry as each one's prior. */
ba::Problem initialPoses(const std::vector<const CreationView*>& views, const CLandmarkCreator::TOptions& o)
{
	const CreationView& last = *views.back();
	ba::Problem problem;
	problem.camera = last.features.camera;
	problem.poses.push_back({});
	for (size_t v = 0; v + 1 < views.size(); v++)
	{
		ba::PosePrior prior;
		prior.camera = static_cast<int>(v) + 1;
		prior.sigmaRotation = o.odometry_sigma_deg * M_PI / 180;
		problem.poses.push_back(relativePose(views[v]->cameraPose, last.cameraPose));
		prior.pose = problem.poses.back();
		prior.sigmaTranslation = std::max(1e-3, o.odometry_sigma_rel * prior.pose.centre().norm());
		problem.priors.push_back(prior);
	}
	return problem;
}

/** The essential matrix between the newest and the oldest view: tracks
 * that break its epipolar geometry are dropped as mismatches, and its
 * rotation replaces the odometry's. */
void correctOldestPoseFromImages(const std::vector<const CreationView*>& views, ba::Problem& problem,
	std::vector<std::vector<int>>& tracks, CreationResult& result)
{
	const CreationView& last = *views.back();
	std::vector<cv::Point2f> pl, p0;
	for (const auto& t : tracks)
	{
		pl.push_back(last.features.pixels[t[0]]);
		p0.push_back(views[0]->features.pixels[t[1]]);
	}
	ba::CameraPose fromImages;
	std::vector<bool> inlier;
	if (!poseFromImages(problem.camera, pl, p0, problem.poses[1], fromImages, inlier)) return;
	std::vector<std::vector<int>> kept;
	for (size_t k = 0; k < tracks.size(); k++)
		if (inlier[k]) kept.push_back(std::move(tracks[k]));
	tracks = std::move(kept);
	// Keep the middle views consistent: apply the same correction.
	const Eigen::Matrix3d dR = fromImages.R * problem.poses[1].R.transpose();
	for (size_t v = 2; v < problem.poses.size(); v++) problem.poses[v].R = dR * problem.poses[v].R;
	problem.poses[1] = fromImages;
	result.rotationFromImages = true;
}

/** Each track triangulated, if in front of every camera, with its
 * observations added to the problem; the track of each point. */
std::vector<int> triangulateTracks(
	const std::vector<const CreationView*>& views, const std::vector<std::vector<int>>& tracks, ba::Problem& problem)
{
	const int n = static_cast<int>(views.size());
	const CreationView& last = *views.back();
	const auto pixelOf = [&](int view, const std::vector<int>& t) {
		// view 0 of the problem is the newest image (track index 0)
		const auto& px = view == 0 ? last.features.pixels[t[0]] : views[view - 1]->features.pixels[t[view]];
		return Eigen::Vector2d(px.x, px.y);
	};
	std::vector<int> trackOfPoint;
	for (size_t k = 0; k < tracks.size(); k++)
	{
		std::vector<Eigen::Vector2d> px;
		for (int v = 0; v < n; v++) px.push_back(pixelOf(v, tracks[k]));
		Eigen::Vector3d X;
		if (!ba::triangulate(problem.camera, problem.poses, px, X)) continue;
		bool inFront = true;
		for (const auto& p : problem.poses) inFront = inFront && p.map(X).z() > 0;
		if (!inFront) continue;
		const int i = static_cast<int>(problem.points.size());
		problem.points.push_back(X);
		trackOfPoint.push_back(static_cast<int>(k));
		for (int v = 0; v < n; v++) problem.observations.push_back({v, i, px[v]});
	}
	return trackOfPoint;
}

/** Each point's largest reprojection error (infinite behind a camera). */
std::vector<double> maxErrorOfPoint(const ba::Problem& p)
{
	std::vector<double> e(p.points.size(), 0);
	for (const auto& ob : p.observations)
	{
		const double r = p.poses[ob.camera].map(p.points[ob.point]).z() > 0 ? ba::residual(p, ob).norm()
																			 : std::numeric_limits<double>::infinity();
		e[ob.point] = std::max(e[ob.point], r);
	}
	return e;
}

/** Refines, drops the points far off (beyond 3 x maxReprojectionPx) and
 * refines again. */
void refineWithoutGrossOutliers(ba::Problem& problem, std::vector<int>& trackOfPoint, double maxReprojectionPx)
{
	ba::refine(problem);
	const auto err = maxErrorOfPoint(problem);
	ba::Problem kept;
	kept.camera = problem.camera;
	kept.poses = problem.poses;
	kept.priors = problem.priors;
	std::vector<int> keptTracks;
	std::vector<int> newIndex(problem.points.size(), -1);
	for (size_t i = 0; i < problem.points.size(); i++)
		if (err[i] <= 3 * maxReprojectionPx)
		{
			newIndex[i] = static_cast<int>(kept.points.size());
			kept.points.push_back(problem.points[i]);
			keptTracks.push_back(trackOfPoint[i]);
		}
	for (const auto& ob : problem.observations)
		if (newIndex[ob.point] >= 0) kept.observations.push_back({ob.camera, newIndex[ob.point], ob.pixel});
	problem = std::move(kept);
	trackOfPoint = std::move(keptTracks);
	ba::refine(problem);
}

/** The well-conditioned points (reprojection error, depth, parallax between
 * two cameras), smallest error first, at most max_points. */
std::vector<int> wellConditionedPoints(
	const ba::Problem& problem, const std::vector<double>& err, const CLandmarkCreator::TOptions& o)
{
	std::vector<Eigen::Vector3d> centres;
	for (const auto& p : problem.poses) centres.push_back(p.centre());
	const double minParallax = o.min_parallax_deg * M_PI / 180;
	std::vector<int> good;
	for (size_t i = 0; i < problem.points.size(); i++)
	{
		const Eigen::Vector3d& X = problem.points[i];
		if (!(err[i] <= o.max_reprojection_px) || X.norm() > o.max_depth) continue;
		double parallax = 0;
		for (size_t a = 0; a < centres.size(); a++)
			for (size_t b = a + 1; b < centres.size(); b++)
				parallax = std::max(parallax, angleBetween(X - centres[a], X - centres[b]));
		if (parallax >= minParallax) good.push_back(static_cast<int>(i));
	}
	std::stable_sort(good.begin(), good.end(), [&](int a, int b) { return err[a] < err[b]; });
	if (static_cast<int>(good.size()) > o.max_points) good.resize(o.max_points);
	return good;
}

/** The landmark of the chosen points: in the newest robot frame, each with
 * the newest view's descriptor (and its depth std where an option uses it). */
VisualLandmarkModel landmarkOf(const ba::Problem& problem, const std::vector<int>& good,
	const std::vector<float>& depthStd, const std::vector<int>& featureOfPoint, const CreationView& last,
	const mrpt::poses::CPose3D& mount, int views)
{
	VisualLandmarkModel lm;
	lm.views = views;
	lm.createdAt = last.time;
	lm.lastSeen = last.time;
	lm.descriptors = cv::Mat(static_cast<int>(good.size()), last.features.descriptors.cols, CV_32F);
	for (size_t r = 0; r < good.size(); r++)
	{
		const int i = good[r];
		const Eigen::Vector3d& X = problem.points[i];
		double xr = 0, yr = 0, zr = 0;
		mount.composePoint(X.x(), X.y(), X.z(), xr, yr, zr);
		lm.points.emplace_back(static_cast<float>(xr), static_cast<float>(yr), static_cast<float>(zr));
		if (!depthStd.empty()) lm.depthStd.push_back(depthStd[i]);
		last.features.descriptors.row(featureOfPoint[i]).copyTo(lm.descriptors.row(static_cast<int>(r)));
	}
	double sq = 0;
	size_t count = 0;
	for (const auto& ob : problem.observations)
		if (std::find(good.begin(), good.end(), ob.point) != good.end())
		{
			sq += ba::residual(problem, ob).squaredNorm();
			count++;
		}
	lm.reprojectionRms = count ? std::sqrt(sq / count) : 0;
	return lm;
}
}  // namespace

CreationResult CLandmarkCreator::create(
	const std::vector<const CreationView*>& views, const mrpt::poses::CPose3D& mount) const
{
	const TOptions& o = m_options;
	CreationResult result;
	const int n = static_cast<int>(views.size());
	if (n < 2)
	{
		result.why = "fewer than two views";
		return result;
	}
	std::vector<std::vector<int>> tracks = matchTracks(views, m_matchRatio);
	result.tracks = static_cast<int>(tracks.size());
	if (result.tracks < o.min_points)
	{
		result.why = "only " + std::to_string(result.tracks) + " features matched across the views";
		return result;
	}
	ba::Problem problem = initialPoses(views, o);
	const double baseline = problem.poses[1].t.norm();
	correctOldestPoseFromImages(views, problem, tracks, result);
	std::vector<int> trackOfPoint = triangulateTracks(views, tracks, problem);
	refineWithoutGrossOutliers(problem, trackOfPoint, o.max_reprojection_px);

	// Scale from odometry: the oldest camera's distance.
	const double estimated = problem.poses[1].centre().norm();
	if (!(estimated > 1e-9) || !(baseline > 0))
	{
		result.why = "no baseline between the views";
		return result;
	}
	const double s = baseline / estimated;
	for (auto& p : problem.poses) p.t *= s;
	for (auto& X : problem.points) X *= s;

	const auto err = maxErrorOfPoint(problem);
	const std::vector<int> good = wellConditionedPoints(problem, err, o);
	result.inliers = static_cast<int>(good.size());
	if (result.inliers < o.min_points)
	{
		result.why = "only " + std::to_string(result.inliers) + " well-conditioned 3-D points";
		return result;
	}
	const std::vector<float> depthStd = m_keepDepthStd  // each point's, only where recognition uses it
		? relativeDepthStds(problem, pixelNoiseOf(problem, err, o.max_reprojection_px))
		: std::vector<float>();
	std::vector<int> featureOfPoint;  // in the newest view
	for (const int track : trackOfPoint) featureOfPoint.push_back(tracks[track][0]);
	result.landmark = landmarkOf(problem, good, depthStd, featureOfPoint, *views.back(), mount, n);
	for (int v = 1; v < n; v++) result.refinedPoses.emplace_back(problem.poses[v].R, problem.poses[v].t);
	result.refinedPoses.emplace_back(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
	return result;
}

void CLandmarkCreator::TOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace config;
	views = readCount(c, s, "views", views, 3, 10);
	min_baseline = readDouble(c, s, "min_baseline", min_baseline, Range::positive());
	max_baseline = readDouble(c, s, "max_baseline", max_baseline, Range::positive());
	min_points = readCount(c, s, "min_points", min_points, 6, 100000);
	max_points = readCount(c, s, "max_points", max_points, 6, 100000);
	max_reprojection_px = readDouble(c, s, "max_reprojection_px", max_reprojection_px, Range::positive());
	min_parallax_deg = readDouble(c, s, "min_parallax_deg", min_parallax_deg, Range::closed(0, 90));
	max_depth = readDouble(c, s, "max_depth", max_depth, Range::positive());
	odometry_sigma_deg = readDouble(c, s, "odometry_sigma_deg", odometry_sigma_deg, Range{0, 90, false, true});
	odometry_sigma_rel = readDouble(c, s, "odometry_sigma_rel", odometry_sigma_rel, Range{0, 10, false, true});
	if (max_baseline < min_baseline) throw ConfigError("[" + s + "] max_baseline must be >= min_baseline");
	if (max_points < min_points) throw ConfigError("[" + s + "] max_points must be >= min_points");
}

void CLandmarkCreator::TOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "views", views, 30, 10, "Images a new landmark is built from (>= 3)");
	c.write(s, "min_baseline", min_baseline, 30, 10, "Robot travel between creation views [m]");
	c.write(s, "max_baseline", max_baseline, 30, 10, "Views older than this travel are dropped [m]");
	c.write(s, "min_points", min_points, 30, 10, "Good 3-D points a landmark needs");
	c.write(s, "max_points", max_points, 30, 10, "Points kept per landmark at most");
	c.write(s, "max_reprojection_px", max_reprojection_px, 30, 10, "Point reprojection error limit, every view [px]");
	c.write(s, "min_parallax_deg", min_parallax_deg, 30, 10, "Widest angle between a point's rays at least [deg]");
	c.write(s, "max_depth", max_depth, 30, 10, "Points farther from the landmark frame are dropped [m]");
	c.write(s, "odometry_sigma_deg", odometry_sigma_deg, 30, 10, "Odometry heading uncertainty between creation views [deg]");
	c.write(s, "odometry_sigma_rel", odometry_sigma_rel, 30, 10, "Odometry translation uncertainty per distance travelled");
}

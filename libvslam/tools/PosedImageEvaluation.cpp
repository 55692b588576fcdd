#include <libvslam/core/InputError.h>
#include <libvslam/frontend/DescriptorCodec.h>
#include <libvslam/frontend/ImageFeatures.h>
#include <libvslam/frontend/LandmarkCreator.h>
#include <libvslam/frontend/LandmarkRecognizer.h>
#include <libvslam/tools/PosedImageEvaluation.h>
#include <mrpt/img/CImage.h>
#include <mrpt/img/TCamera.h>
#include <mrpt/math/CMatrixFixed.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <random>
#include <sstream>

using namespace vslam;

namespace
{
constexpr double kDeg = M_PI / 180;

/** The camera in the robot frame it stands for (robotPoseOfCamera). */
mrpt::poses::CPose3D mountOfView(const StrechaView& v)
{
	const se2::Pose r = robotPoseOfCamera(v);
	Eigen::Matrix3d flip = Eigen::Vector3d(1, -1, -1).asDiagonal();
	const Eigen::Matrix3d Rworld = flip * v.R;  // camera -> z-up world
	const Eigen::Matrix3d Rrobot = Eigen::AngleAxisd(r.phi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	mrpt::math::CMatrixDouble44 T = mrpt::math::CMatrixDouble44::Identity();
	const Eigen::Matrix3d Rmount = Rrobot.transpose() * Rworld;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++) T(i, j) = Rmount(i, j);
	return mrpt::poses::CPose3D(T);
}

/** The mount a robot would have calibrated: the mean of the views' mounts
 * (their pitch and roll vary by a few degrees around a common tilt). */
mrpt::poses::CPose3D calibratedMount(const std::vector<StrechaView>& views)
{
	double yaw = 0, pitch = 0, roll = 0;
	for (const auto& v : views)
	{
		const auto m = mountOfView(v);
		yaw += m.yaw();
		pitch += m.pitch();
		roll += m.roll();
	}
	const double n = static_cast<double>(views.size());
	return {0, 0, 0, yaw / n, pitch / n, roll / n};
}

double seconds(std::chrono::steady_clock::time_point since)
{
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

double median(std::vector<double> v)
{
	if (v.empty()) return NAN;
	std::sort(v.begin(), v.end());
	const size_t n = v.size();
	return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
}  // namespace

se2::Pose vslam::robotPoseOfCamera(const StrechaView& v)
{
	// World turned by 180 deg about x: z up.
	const Eigen::Vector3d axis(v.R(0, 2), -v.R(1, 2), -v.R(2, 2));
	return {v.C.x(), -v.C.y(), std::atan2(axis.y(), axis.x())};
}

namespace
{
/** Every view's features, their codes in the database's matching space. */
std::vector<ImageFeatures> featuresOfViews(
	const std::vector<StrechaView>& views, const CFeatureExtractor::TOptions& featureOptions,
	const CImageCalibration::TOptions& camera, const DescriptorCodec& codec)
{
	const CFeatureExtractor extractor(featureOptions);
	std::vector<ImageFeatures> features;
	for (const auto& v : views)
	{
		mrpt::img::CImage image;
		if (!image.loadFromFile(v.imageFile)) throw InputError("cannot read image '" + v.imageFile + "'");
		mrpt::img::TCamera cam;
		cam.ncols = v.width;
		cam.nrows = v.height;
		cam.setIntrinsicParamsFromValues(v.K(0, 0), v.K(1, 1), v.K(0, 2), v.K(1, 2));
		cam.k1(v.distortion[0]);
		cam.k2(v.distortion[1]);
		cam.k3(v.distortion[2]);
		const auto calib = CImageCalibration::from(
			cam, static_cast<int>(image.getWidth()), static_cast<int>(image.getHeight()), camera, v.imageFile);
		features.push_back(extractor.extract(image.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY), calib));
		features.back().codes = codec.toMatchingSpace(features.back().descriptors);
	}
	return features;
}

/** The k views from \a first as landmark creation sees them, their poses
 * from odometry: the true increments plus noise (one generator and one
 * distribution for the whole evaluation: the distribution keeps a drawn
 * value between calls). */
std::vector<CreationView> creationViews(const std::vector<ImageFeatures>& features, const std::vector<se2::Pose>& robot,
	int first, int k, const mrpt::poses::CPose3D& mount, const TPosedImageEvaluationOptions& o, std::mt19937& rng,
	std::normal_distribution<double>& gauss)
{
	std::vector<CreationView> creation(k);
	se2::Pose odo = robot[first];
	for (int j = 0; j < k; j++)
	{
		if (j > 0)
		{
			const se2::Pose inc = se2::between(robot[first + j - 1], robot[first + j]);
			const double len = std::hypot(inc.x, inc.y);
			const se2::Pose noisy{inc.x + gauss(rng) * o.odometryTranslationNoise * len,
				inc.y + gauss(rng) * o.odometryTranslationNoise * len, inc.phi + gauss(rng) * o.odometryHeadingNoiseDeg * kDeg};
			odo = se2::compose(odo, noisy);
		}
		creation[j].features = features[first + j];
		creation[j].cameraPose = mrpt::poses::CPose3D(odo.x, odo.y, 0, odo.phi, 0, 0) + mount;
		creation[j].time = first + j;
	}
	return creation;
}

/** Creation accuracy: the oldest view's refined pose against the truth. */
void recordCreationAccuracy(const StrechaView& a, const StrechaView& b, const CreationResult& created, PosedImageEvaluation& out)
{
	const Eigen::Matrix3d Rtrue = a.R.transpose() * b.R;  // X_a = R X_b + t
	const Eigen::Vector3d ttrue = a.R.transpose() * (b.C - a.C);
	const auto& [R, t] = created.refinedPoses.front();
	out.creationRotationErrorDeg.push_back(Eigen::AngleAxisd(R * Rtrue.transpose()).angle() / kDeg);
	out.creationDirectionErrorDeg.push_back(std::acos(std::clamp(t.normalized().dot(ttrue.normalized()), -1.0, 1.0)) / kDeg);
	out.creationScaleError.push_back(t.norm() / ttrue.norm() - 1);
}
}  // namespace

PosedImageEvaluation vslam::evaluatePosedImages(
	const std::vector<StrechaView>& views, const CVisualFrontEnd::TOptions& fe,
	const TPosedImageEvaluationOptions& o)
{
	PosedImageEvaluation out;
	const int n = static_cast<int>(views.size());
	const mrpt::poses::CPose3D mount = calibratedMount(views);
	out.mount = mount;
	const DescriptorCodec codec(DescriptorCodec::parse(fe.database.descriptor_storage), fe.database.descriptor_dims);
	auto t0 = std::chrono::steady_clock::now();
	const std::vector<ImageFeatures> features = featuresOfViews(views, fe.features, fe.camera, codec);
	out.featureSeconds = seconds(t0);
	std::vector<se2::Pose> robot;
	for (const auto& v : views) robot.push_back(robotPoseOfCamera(v));

	std::mt19937 rng(o.seed);
	std::normal_distribution<double> gauss;
	const CLandmarkCreator creator = fe.creator();
	const CLandmarkRecognizer recognizer = fe.recognizer();
	const int k = fe.creation.views;
	for (int first = 0; first + k <= n; first++)
	{
		const std::vector<CreationView> creation = creationViews(features, robot, first, k, mount, o, rng, gauss);
		std::vector<const CreationView*> ptrs;
		for (const auto& c : creation) ptrs.push_back(&c);
		t0 = std::chrono::steady_clock::now();
		auto created = creator.create(ptrs, mount);
		out.creationSeconds += seconds(t0);
		out.landmarksTried++;
		if (!created.landmark) continue;
		out.landmarksCreated++;
		const int frameView = first + k - 1;
		recordCreationAccuracy(views[first], views[frameView], created, out);
		created.landmark->id = frameView;
		created.landmark->descriptors = codec.encode(created.landmark->descriptors);  // as the database stores it
		out.landmarkBytes.push_back(static_cast<double>(created.landmark->bytes()));
		for (int q = 0; q < n; q++)
		{
			if (q >= first && q <= frameView) continue;
			RecognitionRecord r;
			r.landmarkView = frameView;
			r.queryView = q;
			const se2::Pose truth = se2::between(robot[q], robot[frameView]);
			r.distance = std::hypot(truth.x, truth.y);
			r.viewpointChangeDeg = std::abs(se2::wrap(robot[q].phi - robot[frameView].phi)) / kDeg;
			t0 = std::chrono::steady_clock::now();
			const auto m = recognizer.recognize(features[q], *created.landmark, mount);
			out.recognitionSeconds += seconds(t0);
			if (m)
			{
				r.recognized = true;
				const auto& p = m->landmarkInRobot;
				r.headingErrorDeg = std::abs(se2::wrap(p.phi() - truth.phi)) / kDeg;
				r.translationError = std::hypot(p.x() - truth.x, p.y() - truth.y);
				r.NPoints = m->NPoints;
				r.ProjErrRMS = m->ProjErrRMS;
				r.Slope = m->Slope;
			}
			out.records.push_back(r);
		}
	}
	return out;
}

std::string vslam::formatPosedImageEvaluation(const std::string& title, const PosedImageEvaluation& e)
{
	std::vector<double> heading, relTrans, trans;
	size_t recognized = 0;
	for (const auto& r : e.records)
		if (r.recognized)
		{
			recognized++;
			heading.push_back(r.headingErrorDeg);
			trans.push_back(r.translationError);
			relTrans.push_back(100 * r.translationError / std::max(r.distance, 1e-9));
		}
	std::ostringstream s;
	s << std::fixed;
	s << "| set | landmarks built / tried | view pairs tried | recognized | median heading error [deg] "
		 "| median translation error [% of distance] | median translation error | 90th pct. heading [deg] |\n"
	  << "|---|---|---|---|---|---|---|---|\n";
	std::vector<double> sortedHeading = heading;
	std::sort(sortedHeading.begin(), sortedHeading.end());
	const double p90 = sortedHeading.empty() ? NAN : sortedHeading[std::min(sortedHeading.size() - 1, size_t(0.9 * sortedHeading.size()))];
	s << "| " << title << " | " << e.landmarksCreated << " / " << e.landmarksTried << " | " << e.records.size()
	  << " | " << recognized << " (" << std::setprecision(1)
	  << (e.records.empty() ? 0.0 : 100.0 * recognized / e.records.size()) << "%) | " << std::setprecision(3)
	  << median(heading) << " | " << median(relTrans) << " | " << median(trans) << " | " << p90 << " |\n\n";

	s << "| viewpoint change [deg] | view pairs | recognized | median heading error [deg] | median translation error [%] |\n"
	  << "|---|---|---|---|---|\n";
	const double edges[] = {0, 10, 20, 30, 45, 60, 90, 180.1};
	for (size_t b = 0; b + 1 < std::size(edges); b++)
	{
		size_t tried = 0, ok = 0;
		std::vector<double> h, t;
		for (const auto& r : e.records)
			if (r.viewpointChangeDeg >= edges[b] && r.viewpointChangeDeg < edges[b + 1])
			{
				tried++;
				if (!r.recognized) continue;
				ok++;
				h.push_back(r.headingErrorDeg);
				t.push_back(100 * r.translationError / std::max(r.distance, 1e-9));
			}
		if (!tried) continue;
		s << "| " << std::setprecision(0) << edges[b] << "-" << std::min(180.0, edges[b + 1]) << " | " << tried
		  << " | " << ok << " (" << std::setprecision(1) << 100.0 * ok / tried << "%) | " << std::setprecision(3)
		  << median(h) << " | " << median(t) << " |\n";
	}
	std::vector<double> scaleAbs;
	for (double v : e.creationScaleError) scaleAbs.push_back(100 * std::abs(v));
	s << "\nLandmark creation, oldest view against the truth (medians): rotation " << std::setprecision(3)
	  << median(e.creationRotationErrorDeg) << " deg, baseline direction " << median(e.creationDirectionErrorDeg)
	  << " deg, baseline length " << median(scaleAbs) << " %\n";
	double bytesSum = 0, bytesMax = 0;
	for (double b : e.landmarkBytes) bytesSum += b, bytesMax = std::max(bytesMax, b);
	s << "Landmark memory: mean " << std::setprecision(0) << (e.landmarkBytes.empty() ? 0 : bytesSum / e.landmarkBytes.size())
	  << " bytes, max " << bytesMax << " bytes\n";
	s << "Camera mount (mean of the views): yaw " << std::setprecision(2) << e.mount.yaw() / kDeg
	  << " deg, pitch " << e.mount.pitch() / kDeg << " deg, roll " << e.mount.roll() / kDeg << " deg\n";
	s << "Time: features " << std::setprecision(2) << e.featureSeconds << " s, creation " << e.creationSeconds
	  << " s, recognition " << e.recognitionSeconds << " s\n";
	return s.str();
}

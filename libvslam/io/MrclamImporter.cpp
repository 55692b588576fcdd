#include <libvslam/core/InputError.h>
#include <libvslam/io/MrclamImporter.h>
#include <libvslam/io/OdometryDelay.h>
#include <libvslam/io/NumericTable.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationBearingRange.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

namespace vslam
{
namespace
{
/** Dead reckoning from (time, v, omega) rows, each held until the next. */
class OdometryIntegrator
{
   public:
	explicit OdometryIntegrator(std::vector<std::vector<double>> rows) : m_rows(std::move(rows))
	{
		m_t = m_rows.front()[0];
	}
	double startTime() const { return m_rows.front()[0]; }
	double endTime() const { return m_rows.back()[0]; }

	/** The odometry pose at time t >= the last query. */
	const se2::Pose& advanceTo(double t)
	{
		while (m_t < t && m_k + 1 < m_rows.size())
		{
			const double segEnd = std::min(t, m_rows[m_k + 1][0]);
			arc(m_rows[m_k][1], m_rows[m_k][2], segEnd - m_t);
			m_t = segEnd;
			if (m_t >= m_rows[m_k + 1][0]) m_k++;
		}
		return m_pose;
	}

   private:
	std::vector<std::vector<double>> m_rows;
	size_t m_k = 0;
	double m_t = 0;
	se2::Pose m_pose{0, 0, 0};

	void arc(double v, double w, double dt)
	{
		if (dt <= 0) return;
		const double dth = w * dt;
		const se2::Pose inc = std::abs(w) < 1e-12
			? se2::Pose{v * dt, 0, 0}
			: se2::Pose{v / w * std::sin(dth), v / w * (1 - std::cos(dth)), dth};
		m_pose = se2::compose(m_pose, inc);
	}
};

std::string robotFile(const std::string& dir, int robot, const char* kind)
{
	return (std::filesystem::path(dir) / ("Robot" + std::to_string(robot) + "_" + kind + ".dat"))
		.string();
}

/** An integer column (barcode, subject number): integral and of a sane size. */
int integerField(double v, const std::string& file, size_t row)
{
	if (v != std::floor(v) || std::abs(v) > 1e9)
		throw InputError("'" + file + "': data row " + std::to_string(row + 1) +
			": expected an integer ID, got " + std::to_string(v));
	return static_cast<int>(v);
}

void checkSorted(const std::vector<std::vector<double>>& rows, const std::string& file)
{
	for (size_t i = 1; i < rows.size(); i++)
		if (rows[i][0] < rows[i - 1][0])
			throw InputError("'" + file + "': times go backwards at data row " + std::to_string(i + 1));
}
using Detections = std::map<double, std::vector<mrpt::obs::CObservationBearingRange::TMeasurement>>;

constexpr int kFalseBarcode = -1;

/** The subject a measurement row's barcode names (kFalseBarcode: none). */
int subjectOf(const std::vector<double>& row, const std::string& measFile, size_t i,
	const std::map<int, int>& subjectOfBarcode)
{
	const auto it = subjectOfBarcode.find(integerField(row[1], measFile, i));
	return it == subjectOfBarcode.end() ? kFalseBarcode : it->second;
}

/** Subjects 1..5 are the robots; the landmarks are 6..20. */
bool isRobot(int subject) { return subject <= 5; }

/** The landmark detections by image time, within the odometry's span;
 * robots seen, false barcodes and detections outside the span counted. */
Detections landmarkDetections(const std::vector<std::vector<double>>& measRows, const std::string& measFile,
	const std::map<int, int>& subjectOfBarcode, double tOdo, double tEnd, MrclamImport& out)
{
	Detections images;
	for (size_t i = 0; i < measRows.size(); i++)
	{
		const auto& r = measRows[i];
		const int subject = subjectOf(r, measFile, i, subjectOfBarcode);
		if (subject == kFalseBarcode)
		{
			out.droppedFalseBarcodes++;
			continue;
		}
		if (isRobot(subject))
		{
			out.droppedRobotSightings++;
			continue;
		}
		if (r[0] < tOdo || r[0] > tEnd)
		{
			out.droppedOutsideOdometry++;
			continue;
		}
		mrpt::obs::CObservationBearingRange::TMeasurement m;
		m.range = static_cast<float>(r[2]);
		m.yaw = static_cast<float>(r[3]);
		m.pitch = 0;
		m.landmarkID = subject;
		images[r[0]].push_back(m);
		out.measurementsUsed++;
	}
	if (images.empty()) throw InputError("'" + measFile + "' has no landmark detection");
	return images;
}

/** The landmark sightings (robots and false barcodes left out). */
std::vector<BearingSighting> sightingsOf(const std::vector<std::vector<double>>& measRows,
	const std::string& measFile, const std::map<int, int>& subjectOfBarcode)
{
	std::vector<BearingSighting> sightings;
	for (size_t i = 0; i < measRows.size(); i++)
	{
		const auto& r = measRows[i];
		const int subject = subjectOf(r, measFile, i, subjectOfBarcode);
		if (subject != kFalseBarcode && !isRobot(subject)) sightings.push_back({r[0], subject, r[2], r[3]});
	}
	return sightings;
}

/** Moves the odometry rows' times by the delay given, or else by the one
 * the sightings show (none if they cannot tell). */
void shiftOdometry(std::vector<std::vector<double>>& odoRows, const std::optional<double>& given,
	const std::vector<std::vector<double>>& measRows, const std::string& measFile,
	const std::map<int, int>& subjectOfBarcode, MrclamImport& out)
{
	std::optional<double> delay = given;
	if (!delay)
	{
		delay = estimateOdometryDelay(odoRows, sightingsOf(measRows, measFile, subjectOfBarcode));
		out.odometryDelayEstimated = delay.has_value();
	}
	out.odometryDelay = delay.value_or(0);
	for (auto& r : odoRows) r[0] += out.odometryDelay;
}

/** Step times from t0: every image, and fillers so that no two steps are
 * more than maxGap apart, up to tEnd. */
std::vector<double> stepTimes(const Detections& images, double t0, double tEnd, double maxGap)
{
	std::vector<double> times{t0};
	double last = t0;
	const auto fillTo = [&](double t) {
		const int n = static_cast<int>(std::ceil((t - last) / maxGap - 1e-9));
		for (int i = 1; i < n; i++) times.push_back(last + (t - last) * i / n);
		times.push_back(t);
		last = t;
	};
	for (const auto& [t, ms] : images)
		if (t > t0) fillTo(t);
	if (last < tEnd) fillTo(tEnd);
	return times;
}

/** The odometry increment as MRPT stores it: the increment plus motion-model
 * options from which MRPT recomputes the covariance when reading. Its
 * Gaussian model with a1..a4 = 0 gives diag(minStdXY^2, minStdXY^2,
 * minStdPHI^2), exactly our motion model's (with its floor; isotropic in
 * xy, so frame-free). */
mrpt::obs::CActionCollection::Ptr odometryAction(const CMotionModel& motion, const se2::Pose& inc, mrpt::Clock::time_point stamp)
{
	const Eigen::Matrix3d C = motion.incrementCovariance(inc) + motion.covarianceFloor();
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions mm;
	mm.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
	mm.gaussianModel.a1 = mm.gaussianModel.a2 = mm.gaussianModel.a3 = mm.gaussianModel.a4 = 0;
	mm.gaussianModel.minStdXY = std::sqrt(C(0, 0));
	mm.gaussianModel.minStdPHI = std::sqrt(C(2, 2));
	mrpt::obs::CActionRobotMovement2D mv;
	mv.computeFromOdometry(mrpt::poses::CPose2D(inc), mm);
	mv.timestamp = stamp;
	auto acts = mrpt::obs::CActionCollection::Create();
	acts->insert(mv);
	return acts;
}
}  // namespace

MrclamImport importMrclam(const std::string& dir, const TMrclamImportOptions& o)
{
	if (o.robot < 1 || o.robot > 5)
		throw InputError("MRCLAM robot must be 1..5, got " + std::to_string(o.robot));
	if (!(o.max_step_gap > 0)) throw InputError("max_step_gap must be > 0");
	const std::string barcodesFile = (std::filesystem::path(dir) / "Barcodes.dat").string();
	const std::string landmarksFile =
		(std::filesystem::path(dir) / "Landmark_Groundtruth.dat").string();
	const std::string odoFile = robotFile(dir, o.robot, "Odometry");
	const std::string measFile = robotFile(dir, o.robot, "Measurement");
	const std::string gtFile = robotFile(dir, o.robot, "Groundtruth");

	std::map<int, int> subjectOfBarcode;
	const auto barcodeRows = readNumericTable(barcodesFile, "#", 2);
	for (size_t i = 0; i < barcodeRows.size(); i++)
		subjectOfBarcode[integerField(barcodeRows[i][1], barcodesFile, i)] =
			integerField(barcodeRows[i][0], barcodesFile, i);
	auto odoRows = readNumericTable(odoFile, "#", 3);
	const auto measRows = readNumericTable(measFile, "#", 4);
	Trajectory gtWorld;
	for (const auto& r : readNumericTable(gtFile, "#", 4)) gtWorld.push_back({r[0], {r[1], r[2], r[3]}});
	if (odoRows.size() < 2) throw InputError("'" + odoFile + "' has fewer than 2 rows");
	if (gtWorld.empty()) throw InputError("'" + gtFile + "' is empty");
	checkSorted(odoRows, odoFile);
	checkSorted(measRows, measFile);

	MrclamImport out;
	shiftOdometry(odoRows, o.odometry_delay, measRows, measFile, subjectOfBarcode, out);
	out.odometryRows = odoRows.size();
	out.measurementRows = measRows.size();
	OdometryIntegrator odometry(odoRows);
	const double tOdo = odometry.startTime(), tEnd = odometry.endTime();
	const Detections images = landmarkDetections(measRows, measFile, subjectOfBarcode, tOdo, tEnd, out);
	// Start: the first image with a landmark detection. Some robots turn
	// before that; MRPT's kf-slam ignores odometry until its map holds a
	// landmark, so starting earlier would hand it a wrong start heading.
	const double t0 = images.begin()->first;
	const auto start = interpolate(gtWorld, t0, 1.0);
	if (!start)
		throw InputError("'" + gtFile + "' has no ground truth at the first detection time " + std::to_string(t0));
	out.startPoseWorld = *start;
	for (const auto& p : gtWorld) out.groundTruth.push_back({p.t, se2::between(out.startPoseWorld, p.pose)});
	const auto landmarkRows = readNumericTable(landmarksFile, "#", 5);
	for (size_t i = 0; i < landmarkRows.size(); i++)
	{
		const auto& r = landmarkRows[i];
		const se2::Pose l = se2::between(out.startPoseWorld, {r[1], r[2], 0});
		out.landmarks.push_back({integerField(r[0], landmarksFile, i), l.x, l.y});
	}
	// Steps at least every max_step_gap: refuse absurd spans (corrupt times)
	// instead of generating billions of steps.
	constexpr double kMaxSteps = 1e7;
	if ((tEnd - t0) / o.max_step_gap > kMaxSteps)
		throw InputError("'" + odoFile + "': odometry spans " + std::to_string(tEnd - t0) + " s, more than " +
			std::to_string(static_cast<long>(kMaxSteps)) + " steps of max_step_gap; are its times corrupt?");

	const CMotionModel motion(o.motion);
	se2::Pose prev = odometry.advanceTo(t0);
	for (double t : stepTimes(images, t0, tEnd, o.max_step_gap))
	{
		const se2::Pose now = odometry.advanceTo(t);
		const auto stamp = mrpt::Clock::fromDouble(t);
		auto acts = odometryAction(motion, se2::between(prev, now), stamp);
		prev = now;
		// Every frame holds an observation, empty between images: MRPT's
		// kf-slam requires one in every sensory frame.
		auto obs = mrpt::obs::CObservationBearingRange::Create();
		obs->timestamp = stamp;
		obs->sensorLabel = "CAMERA_LANDMARKS";
		if (const auto it = images.find(t); it != images.end()) obs->sensedData = it->second;
		obs->sensor_std_range = static_cast<float>(o.std_range);
		obs->sensor_std_yaw = static_cast<float>(o.std_bearing);
		obs->fieldOfView_yaw = static_cast<float>(70 * M_PI / 180);
		obs->validCovariances = false;
		auto sf = mrpt::obs::CSensoryFrame::Create();
		sf->insert(obs);
		out.steps.emplace_back(acts, sf);
	}
	return out;
}

void writeMrclamLandmarks(const std::string& file, const std::vector<MrclamLandmark>& landmarks)
{
	FILE* f = std::fopen(file.c_str(), "wt");
	if (!f) throw InputError("cannot create '" + file + "'");
	std::fprintf(f, "%% subject x y (start frame of the robot)\n");
	for (const auto& l : landmarks) std::fprintf(f, "%d %.6f %.6f\n", l.subject, l.x, l.y);
	std::fclose(f);
}
}  // namespace vslam

/** Camera images through the front-end and the filter, as users run it:
 * vslam on an image rawlog in one run, vslam-frontend alone, determinism
 * with the front-end in the loop, and a missing or corrupt image. Images come from
 * the textured-room fixture (tests/support/RoomImageRawlog.h). */
#include <gtest/gtest.h>
#include <libvslam/app/RunSummary.h>
#include <libvslam/eval/LandmarkScaleOracle.h>
#include <libvslam/io/Trajectory.h>
#include <libvslam/io/CRawlogReader.h>
#include <libvslam/io/RawlogWriting.h>
#include <libvslam/obs/CObservationLandmarkCreated.h>
#include <libvslam/obs/CObservationVisualLandmark.h>
#include <libvslam/obs/registerClasses.h>
#include <mrpt/math/wrap2pi.h>
#include <tests/support/RoomImageRawlog.h>
#include <tests/support/RunCommand.h>
#include <tests/support/TempDir.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <utility>
#include <vector>

using vslam::testing::readFile;
using vslam::testing::lineCount;
using vslam::testing::quoted;
using vslam::testing::runCommand;
using vslam::testing::TempDir;
namespace fs = std::filesystem;

namespace
{
const std::string kBin = std::string(VSLAM_BINARY_DIR) + "/bin/";
/** An INI for vslam on `rawlog` (100 particles, seed 1). */
std::string writeIni(const TempDir& dir, const std::string& rawlog, bool startFromGroundTruth)
{
	const std::string ini = dir.file("run.ini");
	std::ofstream(ini) << "[vslam]\nrawlog_file = " << rawlog << "\nRANDOM_SEED = 1\n"
					   << "ground_truth_file = " << vslam::siblingFile(rawlog, "_groundtruth.tum") << "\n"
					   << "initial_pose_from_ground_truth = " << (startFromGroundTruth ? "true" : "false") << "\n"
					   << "[vslam_particle_filter]\nsampleSize = 100\n";
	return ini;
}

/** A short room rawlog (0.3 laps) with its images in files beside it,
 * `ext_Images/img_N.png`. */
std::string writeExternalImageRawlog(const TempDir& dir)
{
	const std::string rawlog = dir.file("ext.rawlog");
	vslam::testing::TRoomRawlogOptions o;
	o.laps = 0.3;
	o.externalImages = true;
	vslam::testing::writeRoomImageRawlog(rawlog, o);
	return rawlog;
}

/** A number at a dotted path of the run summary (NaN if absent). */
double summaryValue(const std::string& summaryFile, const std::string& path)
{
	return vslam::summaryNumber(vslam::readRunSummary(summaryFile), path);
}
}  // namespace

TEST(VisualPipeline, ImagesInOneRunBeatDeadReckoning)
{
	TempDir dir;
	const std::string rawlog = dir.file("room.rawlog");
	vslam::testing::TRoomRawlogOptions o;
	// A 5% turn bias: the heading drifts (a distance bias would scale the
	// landmarks as well, which no monocular camera can tell).
	o.odometryTurnScale = 1.05;
	o.laps = 2;
	const int images = vslam::testing::writeRoomImageRawlog(rawlog, o);
	const auto r = runCommand(quoted(kBin + "vslam") + " " + quoted(writeIni(dir, rawlog, true)) + " --quiet --out " + quoted(dir.file("out")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const std::string file = dir.file("out/run_summary.yaml");
	const std::string summary = readFile(file);
	EXPECT_EQ(summaryValue(file, "front_end.images"), images) << summary;
	EXPECT_GE(summaryValue(file, "front_end.landmarks_created"), 3) << summary;
	for (const char* why : {"poorly_conditioned", "inconsistent"})
		EXPECT_GE(summaryValue(file, std::string("front_end.recognitions_not_reported.") + why), 0) << summary;
	EXPECT_GT(summaryValue(file, "front_end.measurements"), images / 3) << summary;
	const double vslamRmse = summaryValue(file, "error_vs_ground_truth_m.vslam.rmse");
	const double deadReckoning = summaryValue(file, "error_vs_ground_truth_m.dead_reckoning.rmse");
	EXPECT_GT(vslamRmse, 0) << summary;
	// Measured 0.21 m against 0.36 m: the first lap drifts with the
	// odometry (each landmark is seen only near where it was made); the
	// loop closure brings the error down to a few cm, and the second lap
	// follows the map built on the first.
	EXPECT_LT(vslamRmse, 0.8 * deadReckoning) << summary;
	EXPECT_LT(summaryValue(file, "error_vs_ground_truth_m.vslam.heading_rmse_deg"),
		0.6 * summaryValue(file, "error_vs_ground_truth_m.dead_reckoning.heading_rmse_deg"))
		<< summary;
}

TEST(VisualPipeline, FrontEndAloneThenFilterEqualsOneRunAndRunsRepeatExactly)
{
	TempDir dir;
	const std::string rawlog = dir.file("room.rawlog");
	vslam::testing::writeRoomImageRawlog(rawlog);
	const auto fe = runCommand(quoted(kBin + "vslam-frontend") + " " + quoted(rawlog) + " " + quoted(dir.file("meas.rawlog")));
	ASSERT_EQ(fe.exitCode, 0) << fe.output;
	EXPECT_NE(fe.output.find("landmarks created"), std::string::npos) << fe.output;
	const std::string ini = writeIni(dir, rawlog, false);
	const auto one = runCommand(quoted(kBin + "vslam") + " " + quoted(ini) + " --quiet --out " + quoted(dir.file("one")));
	const auto again = runCommand(quoted(kBin + "vslam") + " " + quoted(ini) + " --quiet --out " + quoted(dir.file("again")));
	const auto split = runCommand(quoted(kBin + "vslam") + " " + quoted(ini) + " " + quoted(dir.file("meas.rawlog")) +
		" --quiet --out " + quoted(dir.file("split")));
	ASSERT_EQ(one.exitCode, 0) << one.output;
	ASSERT_EQ(again.exitCode, 0) << again.output;
	ASSERT_EQ(split.exitCode, 0) << split.output;
	for (const char* f : {"log_estimated_path.txt", "final_map.txt", "log_filter_steps.txt"})
	{
		if (std::string(f) != "log_filter_steps.txt")  // step times differ
		{
			EXPECT_EQ(readFile(dir.file(std::string("one/") + f)), readFile(dir.file(std::string("again/") + f))) << f;
		}
	}
	// Same path; only the first step's time is lost in the measurement
	// rawlog (its one image made no observation and it has no odometry).
	const auto withoutFirstRow = [](const std::string& text) { return text.substr(text.find('\n') + 1); };
	EXPECT_EQ(withoutFirstRow(readFile(dir.file("one/log_estimated_path.txt"))),
		withoutFirstRow(readFile(dir.file("split/log_estimated_path.txt"))));
	// The same map; only the line naming the run differs (two rawlogs).
	const auto withoutRunId = [](std::string text) {
		const auto at = text.find("% vslam run ");
		return at == std::string::npos ? text : text.erase(at, text.find('\n', at) + 1 - at);
	};
	EXPECT_EQ(withoutRunId(readFile(dir.file("one/final_map.txt"))), withoutRunId(readFile(dir.file("split/final_map.txt"))));
}

TEST(VisualPipeline, MissingImageFileNamesTheImageAndTheEntry)
{
	TempDir dir;
	const std::string rawlog = writeExternalImageRawlog(dir);
	fs::remove(dir.file("ext_Images/img_5.png"));
	const auto r = runCommand(quoted(kBin + "vslam") + " " + quoted(writeIni(dir, rawlog, false)) + " --quiet --out " + quoted(dir.file("out")));
	EXPECT_EQ(r.exitCode, 3) << r.output;
	EXPECT_NE(r.output.find("img_5.png"), std::string::npos) << r.output;
	EXPECT_NE(r.output.find("entry 10"), std::string::npos) << r.output;  // the step's first object
	EXPECT_NE(r.output.find("not found"), std::string::npos) << r.output;
	// The steps before the missing image are in the outputs.
	EXPECT_GE(std::count(std::istreambuf_iterator<char>(std::ifstream(dir.file("out/log_estimated_path.txt")).rdbuf()), {}, '\n'), 5);
	const auto fe = runCommand(quoted(kBin + "vslam-frontend") + " " + quoted(rawlog) + " " + quoted(dir.file("m.rawlog")));
	EXPECT_EQ(fe.exitCode, 3) << fe.output;
	EXPECT_NE(fe.output.find("img_5.png"), std::string::npos) << fe.output;
}

namespace
{
struct RecordedMeasurement
{
	double t = 0;
	int64_t id = -1;
	mrpt::poses::CPose2D z;
	vslam::se2::Pose mount{0, 0, 0};  //!< the camera's on the robot, planar
};

/** The landmark measurements of a measurement rawlog, and when each
 * landmark was created. */
std::vector<RecordedMeasurement> readMeasurements(const std::string& file, std::map<int64_t, double>& createdAt)
{
	std::vector<RecordedMeasurement> out;
	vslam::CRawlogReader reader(file);
	vslam::RawlogStep step;
	while (reader.next(step))
		for (const auto& o : *step.sf)
		{
			if (const auto* m = dynamic_cast<const vslam::CObservationVisualLandmark*>(o.get()))
				out.push_back({mrpt::Clock::toDouble(m->timestamp), m->landmarkID, m->relPose,
					{m->sensorPoseOnRobot.x(), m->sensorPoseOnRobot.y(), m->sensorPoseOnRobot.yaw()}});
			else if (const auto* c = dynamic_cast<const vslam::CObservationLandmarkCreated*>(o.get()))
				createdAt[c->landmarkID] = mrpt::Clock::toDouble(c->timestamp);
		}
	return out;
}

/** A rendered room rawlog (1.5 laps) in `dir`, registered classes. */
std::string writeOracleTestRawlog(TempDir& dir)
{
	vslam::registerObservationClasses();
	const std::string rawlog = dir.file("room.rawlog");
	vslam::testing::TRoomRawlogOptions o;
	o.laps = 1.5;
	vslam::testing::writeRoomImageRawlog(rawlog, o);
	return rawlog;
}

/** The landmark frame (the robot's true pose when it was created, at
 * tCreated) seen from the robot's true pose at t. */
std::optional<mrpt::poses::CPose2D> trueMeasurement(const vslam::Trajectory& truth, double t, double tCreated)
{
	const auto now = vslam::interpolate(truth, t, 1.0);
	const auto frame = vslam::interpolate(truth, tCreated, 1.0);
	if (!now || !frame) return std::nullopt;
	return mrpt::poses::CPose2D(frame->x, frame->y, frame->phi) - mrpt::poses::CPose2D(now->x, now->y, now->phi);
}
}  // namespace

TEST(VisualPipeline, CorruptImageFileNamesTheImageAsUnreadable)
{
	TempDir dir;
	const std::string rawlog = writeExternalImageRawlog(dir);
	std::ofstream(dir.file("ext_Images/img_5.png"), std::ios::trunc) << "not a PNG file";
	for (const std::string& command :
		{quoted(kBin + "vslam") + " " + quoted(writeIni(dir, rawlog, false)) + " --quiet --out " + quoted(dir.file("out")),
			quoted(kBin + "vslam-frontend") + " " + quoted(rawlog) + " " + quoted(dir.file("m.rawlog"))})
	{
		const auto r = runCommand(command);
		EXPECT_EQ(r.exitCode, 3) << r.output;
		EXPECT_NE(r.output.find("img_5.png': cannot be read"), std::string::npos) << r.output;
	}
}

TEST(VisualPipeline, OracleRawlogHasTheSameRecognitionsWithTheirTrueMeasurements)
{
	TempDir dir;
	const std::string rawlog = writeOracleTestRawlog(dir);
	const std::string truthFile = vslam::siblingFile(rawlog, "_groundtruth.tum");
	const std::string fe = quoted(kBin + "vslam-frontend") + " " + quoted(rawlog) + " " + quoted(dir.file("m.rawlog"));
	const auto r = runCommand(fe + " --ground-truth " + quoted(truthFile) + " --oracle-rawlog " + quoted(dir.file("oracle.rawlog")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	std::map<int64_t, double> createdAt, createdAtOracle;
	const auto measured = readMeasurements(dir.file("m.rawlog"), createdAt);
	const auto oracle = readMeasurements(dir.file("oracle.rawlog"), createdAtOracle);
	ASSERT_GT(measured.size(), 20u);
	ASSERT_EQ(oracle.size(), measured.size());  // the truth covers the whole run
	EXPECT_EQ(createdAtOracle, createdAt);
	const auto truth = vslam::readTrajectory(truthFile);
	size_t differ = 0;
	for (size_t i = 0; i < oracle.size(); i++)
	{
		EXPECT_EQ(oracle[i].t, measured[i].t);
		EXPECT_EQ(oracle[i].id, measured[i].id);
		const auto expectedIfAny = trueMeasurement(truth, oracle[i].t, createdAt.at(oracle[i].id));
		ASSERT_TRUE(expectedIfAny);
		const mrpt::poses::CPose2D& expected = *expectedIfAny;
		EXPECT_NEAR((oracle[i].z - expected).norm(), 0, 1e-6);
		EXPECT_NEAR(mrpt::math::wrapToPi(oracle[i].z.phi() - expected.phi()), 0, 1e-6);
		EXPECT_LT((measured[i].z - expected).norm(), 0.3);  // the front-end's own error stays small
		differ += (measured[i].z - expected).norm() > 1e-4;
	}
	EXPECT_GT(differ, measured.size() / 2);  // the measured file is not the truth

	const auto noTruth = runCommand(fe + " --oracle-rawlog " + quoted(dir.file("o2.rawlog")));
	EXPECT_EQ(noTruth.exitCode, 1) << noTruth.output;  // a usage error
	EXPECT_NE(noTruth.output.find("--ground-truth"), std::string::npos) << noTruth.output;
}

TEST(VisualPipeline, OracleKindsReplaceOrDropOnlyTheMeasurementsBeyondOrWithinThreeSigma)
{
	TempDir dir;
	const std::string rawlog = writeOracleTestRawlog(dir);
	const std::string truthFile = vslam::siblingFile(rawlog, "_groundtruth.tum");
	// A Sigma_vis small enough that the front-end's errors fall on both sides
	// of 3 sigma (1.5 cm, 0.6 deg).
	const std::string ini = dir.file("sigma.ini");
	std::ofstream(ini) << "[vslam_visual]\nstd_dx = 0.005\nstd_dy = 0.005\nstd_dphi_deg = 0.2\n";
	const std::string fe = quoted(kBin + "vslam-frontend") + " " + quoted(rawlog) + " " + quoted(dir.file("m.rawlog")) +
		" --config " + quoted(ini) + " --ground-truth " + quoted(truthFile);
	for (const char* kind : {"outliers", "drop-outliers"})
	{
		const auto r = runCommand(fe + " --oracle-rawlog " + quoted(dir.file(kind)) + " --oracle-kind " + kind);
		ASSERT_EQ(r.exitCode, 0) << r.output;
	}
	std::map<int64_t, double> createdAt, unused;
	const auto measured = readMeasurements(dir.file("m.rawlog"), createdAt);
	const auto fixed = readMeasurements(dir.file("outliers"), unused);
	const auto dropped = readMeasurements(dir.file("drop-outliers"), unused);
	ASSERT_EQ(fixed.size(), measured.size());
	const auto truth = vslam::readTrajectory(truthFile);
	size_t outliers = 0, kept = 0;
	for (size_t i = 0; i < measured.size(); i++)
	{
		const auto expectedIfAny = trueMeasurement(truth, measured[i].t, createdAt.at(measured[i].id));
		ASSERT_TRUE(expectedIfAny);
		const mrpt::poses::CPose2D& expected = *expectedIfAny;
		// Componentwise, as the accuracy figures count them.
		const bool beyond = std::abs(measured[i].z.x() - expected.x()) > 0.015 ||
			std::abs(measured[i].z.y() - expected.y()) > 0.015 ||
			std::abs(mrpt::math::wrapToPi(measured[i].z.phi() - expected.phi())) > 0.6 * M_PI / 180;
		outliers += beyond;
		// Outliers become the truth, the others stay as measured.
		const mrpt::poses::CPose2D want = beyond ? expected : measured[i].z;
		EXPECT_NEAR((fixed[i].z - want).norm(), 0, 1e-4) << i;
		EXPECT_NEAR(mrpt::math::wrapToPi(fixed[i].z.phi() - want.phi()), 0, 1e-4) << i;
		// drop-outliers keeps the others in order, as measured.
		if (beyond) continue;
		ASSERT_LT(kept, dropped.size());
		EXPECT_EQ(dropped[kept].t, measured[i].t);
		EXPECT_NEAR((dropped[kept].z - measured[i].z).norm(), 0, 1e-9);
		kept++;
	}
	EXPECT_EQ(kept, dropped.size());
	EXPECT_GT(outliers, 0u);
	EXPECT_LT(outliers, measured.size());

	const auto bad = runCommand(fe + " --oracle-rawlog " + quoted(dir.file("x")) + " --oracle-kind some");
	EXPECT_EQ(bad.exitCode, 1) << bad.output;
	EXPECT_NE(bad.output.find("--oracle-kind 'some'"), std::string::npos) << bad.output;
}

TEST(VisualPipeline, ScaleOracleTakesEachLandmarksFittedScaleOutOfAllItsMeasurements)
{
	TempDir dir;
	const std::string rawlog = writeOracleTestRawlog(dir);
	const std::string truthFile = vslam::siblingFile(rawlog, "_groundtruth.tum");
	const std::string fe = quoted(kBin + "vslam-frontend") + " " + quoted(rawlog) + " " + quoted(dir.file("m.rawlog")) +
		" --ground-truth " + quoted(truthFile) + " --oracle-kind scale";
	const auto r = runCommand(fe + " --oracle-rawlog " + quoted(dir.file("scale.rawlog")) + " --oracle-scale-bias 0.02");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	std::map<int64_t, double> createdAt, unused;
	const auto measured = readMeasurements(dir.file("m.rawlog"), createdAt);
	const auto oracle = readMeasurements(dir.file("scale.rawlog"), unused);
	ASSERT_EQ(oracle.size(), measured.size());
	const auto truth = vslam::readTrajectory(truthFile);
	// Each landmark's scale, fitted here over the measurements within 3 sigma
	// of the default Sigma_vis (0.09 m, 2.5 deg).
	std::map<int64_t, std::vector<std::pair<vslam::se2::Pose, vslam::se2::Pose>>> inliers;
	const auto pose = [](const mrpt::poses::CPose2D& p) { return vslam::se2::Pose{p.x(), p.y(), p.phi()}; };
	for (const auto& m : measured)
	{
		const auto expected = trueMeasurement(truth, m.t, createdAt.at(m.id));
		ASSERT_TRUE(expected);
		if (std::abs(m.z.x() - expected->x()) <= 0.27 && std::abs(m.z.y() - expected->y()) <= 0.27 &&
			std::abs(mrpt::math::wrapToPi(m.z.phi() - expected->phi())) <= 7.5 * M_PI / 180)
			inliers[m.id].emplace_back(pose(m.z), pose(*expected));
	}
	std::map<int64_t, double> scaleOf;
	for (const auto& [id, pairs] : inliers) scaleOf[id] = vslam::fitLandmarkScale(pairs, measured.front().mount);
	size_t rescaled = 0;
	for (size_t i = 0; i < measured.size(); i++)
	{
		EXPECT_EQ(oracle[i].t, measured[i].t);
		ASSERT_EQ(oracle[i].id, measured[i].id);
		// The heading is not a length: it stays as measured.
		EXPECT_NEAR(mrpt::math::wrapToPi(oracle[i].z.phi() - measured[i].z.phi()), 0, 1e-9);
		const double k = scaleOf.at(measured[i].id) / 1.02;  // the odometry's own 2% left in
		const auto want = vslam::withoutScale(pose(measured[i].z), measured[i].mount, k);
		EXPECT_NEAR(oracle[i].z.x(), want.x, 1e-6) << i;
		EXPECT_NEAR(oracle[i].z.y(), want.y, 1e-6) << i;
		rescaled += std::abs(k - 1) > 1e-3;
	}
	EXPECT_GT(rescaled, measured.size() / 2);  // the landmarks' scales are not 1 here

	const auto stray = runCommand(fe + " --oracle-rawlog " + quoted(dir.file("x")) + " --oracle-kind all --oracle-scale-bias 0.01");
	EXPECT_EQ(stray.exitCode, 1) << stray.output;
	EXPECT_NE(stray.output.find("--oracle-scale-bias goes with"), std::string::npos) << stray.output;
}

namespace
{
/** The header and the rows of a `vslam-frontend --accuracy-csv` file, each
 * row's values with its text (for messages). */
struct AccuracyCsv
{
	std::string header;
	std::vector<std::pair<std::vector<double>, std::string>> rows;
};

AccuracyCsv readAccuracyCsv(const std::string& file)
{
	AccuracyCsv csv;
	std::ifstream in(file);
	std::getline(in, csv.header);
	for (std::string line; std::getline(in, line);)
	{
		std::vector<double> c;
		std::stringstream ss(line);
		for (std::string cell; std::getline(ss, cell, ',');) c.push_back(std::stod(cell));
		csv.rows.emplace_back(std::move(c), line);
	}
	return csv;
}
}  // namespace

TEST(VisualPipeline, AccuracyCsvCountsBeyondThreeSigmaOfSigmaVisAndOfTheNoiseTheFilterGivesEach)
{
	TempDir dir;
	const std::string rawlog = writeOracleTestRawlog(dir);
	const std::string truthFile = vslam::siblingFile(rawlog, "_groundtruth.tum");
	// Sigma_vis small enough for outliers (as above), and the filter weighing
	// each measurement by its predicted covariance, with a factor that
	// leaves some beyond and takes some in (measured: 28 and 12 of 100).
	const double sx = 0.005, sphiDeg = 0.2, k = 0.5;
	const std::string ini = dir.file("weighted.ini");
	std::ofstream(ini) << "[vslam_visual]\nstd_dx = " << sx << "\nstd_dy = " << sx << "\nstd_dphi_deg = " << sphiDeg
					   << "\npredicted_cov_scale = " << k << "\n";
	const std::string csv = dir.file("accuracy.csv");
	const auto r = runCommand(quoted(kBin + "vslam-frontend") + " " + quoted(rawlog) + " " + quoted(dir.file("m.rawlog")) +
		" --config " + quoted(ini) + " --ground-truth " + quoted(truthFile) + " --accuracy-csv " + quoted(csv));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_NE(r.output.find("beyond 3 sigma of the noise the filter gives each measurement (Sigma_vis + 0.5^2"),
		std::string::npos) << r.output;

	// Recompute both flags from the file's own columns.
	const AccuracyCsv file = readAccuracyCsv(csv);
	ASSERT_NE(file.header.find(",beyond_3_sigma_of_its_noise"), std::string::npos) << file.header;
	size_t rows = 0, beyondVis = 0, beyondOwn = 0;
	for (const auto& [c, line] : file.rows)
	{
		ASSERT_EQ(c.size(), 19u) << line;
		const double ex = std::abs(c[2] - c[5]), ey = std::abs(c[3] - c[6]);
		const double ephi = std::abs(mrpt::math::wrapToPi((c[4] - c[7]) * M_PI / 180)) * 180 / M_PI;
		const bool vis = ex > 3 * sx || ey > 3 * sx || ephi > 3 * sphiDeg;
		const auto own = [&](double s, double predicted) { return 3 * std::sqrt(s * s + k * k * predicted * predicted); };
		const bool wide = ex > own(sx, c[13]) || ey > own(sx, c[14]) || ephi > own(sphiDeg, c[15]);
		// The file rounds to 1e-5 m and 1e-4 deg: a value that close to its
		// threshold may fall either way.
		const auto near = [](double e, double threshold) { return std::abs(e - threshold) < 1e-3 * threshold; };
		const bool onEdge = near(ex, 3 * sx) || near(ey, 3 * sx) || near(ephi, 3 * sphiDeg) || near(ex, own(sx, c[13])) ||
			near(ey, own(sx, c[14])) || near(ephi, own(sphiDeg, c[15]));
		if (!onEdge)
		{
			EXPECT_EQ(c[12] != 0, vis) << line;
			EXPECT_EQ(c[17] != 0, wide) << line;
		}
		rows++, beyondVis += c[12] != 0, beyondOwn += c[17] != 0;
	}
	std::printf("%zu measurements: %zu beyond 3 sigma of Sigma_vis, %zu of the noise the filter gives each\n", rows,
		beyondVis, beyondOwn);
	EXPECT_GT(rows, 10u);
	EXPECT_GT(beyondVis, 0u);
	EXPECT_LE(beyondOwn, beyondVis);  // the filter's noise is never below Sigma_vis
	EXPECT_GT(beyondOwn, 0u);
	EXPECT_LT(beyondOwn, beyondVis);  // and here the weighting takes some in
}

TEST(VisualPipeline, AccuracyFollowsThePreFilterOfTheSetOverridesAndChecksTheirKeys)
{
	TempDir dir;
	const std::string rawlog = writeOracleTestRawlog(dir);
	const std::string truthFile = vslam::siblingFile(rawlog, "_groundtruth.tum");
	const std::string csv = dir.file("accuracy.csv");
	const std::string fe = quoted(kBin + "vslam-frontend") + " " + quoted(rawlog) + " " + quoted(dir.file("m.rawlog")) +
		" --ground-truth " + quoted(truthFile) + " --accuracy-csv " + quoted(csv);
	// A Slope bound tight enough to drop some of the measurements the
	// paper's other two rules accept.
	const double maxSlope = 0.003;
	const auto r = runCommand(fe + " --set vslam_prefilter.max_Slope=" + std::to_string(maxSlope));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const AccuracyCsv file = readAccuracyCsv(csv);
	size_t rows = 0, accepted = 0, droppedForTheSlope = 0;
	for (const auto& [c, line] : file.rows)
	{
		ASSERT_EQ(c.size(), 19u) << line;
		const double slope = std::abs(c[10]);
		const bool paperRules = c[8] <= 3 && c[9] >= 10;
		// The file rounds Slope to 1e-5 rad: too close to the bound to tell.
		if (std::abs(slope - maxSlope) < 2e-5) continue;
		EXPECT_EQ(c[11] != 0, paperRules && slope <= maxSlope) << line;
		rows++, accepted += c[11] != 0;
		droppedForTheSlope += paperRules && slope > maxSlope;
	}
	std::printf("%zu measurements: %zu accepted, %zu dropped for their Slope\n", rows, accepted, droppedForTheSlope);
	EXPECT_GT(accepted, 0u);
	EXPECT_GT(droppedForTheSlope, 0u);

	// A misspelled pre-filter key is an error before the run, naming it.
	const auto bad = runCommand(fe + " --set vslam_prefilter.max_Slop=0.01");
	EXPECT_NE(bad.exitCode, 0) << bad.output;
	EXPECT_NE(bad.output.find("'max_Slop'"), std::string::npos) << bad.output;
	EXPECT_NE(bad.output.find("did you mean 'max_Slope'"), std::string::npos) << bad.output;
}

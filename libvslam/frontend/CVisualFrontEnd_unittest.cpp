/** The whole front-end on an image sequence with exact geometry: a robot
 * drives laps of a circle in a textured room (tests/support/RoomRenderer.h),
 * images at 2 Hz. Landmarks are created on the first lap and recognized on
 * the second; every measurement is compared with the true pose of the
 * landmark frame (the robot pose of the image that created it). */
#include <gtest/gtest.h>
#include <libvslam/frontend/CVisualFrontEnd.h>
#include <mrpt/math/wrap2pi.h>
#include <Eigen/Dense>
#include <tests/support/RoomRenderer.h>

#include <algorithm>
#include <map>
#include <iostream>
#include <random>

using namespace vslam;

namespace
{
constexpr double kDeg = M_PI / 180;

struct LapsResult
{
	size_t images = 0, created = 0;
	std::vector<double> translationErrors, headingErrors;
	/** Each measurement's error, squared, normalized by its predicted covariance. */
	std::vector<double> predictedMahalanobis2;
	std::vector<std::string> rows;  //!< every output, for determinism
	size_t landmarksInDatabase = 0, pruned = 0;
	size_t inconsistent = 0;  //!< recognitions not reported for [vslam_recognition] odometry_gate_s
	/** Per landmark, measured over true range of each measurement from
	 * beyond 0.5 m in the last lap: how far off the landmark's scale is. */
	std::map<int64_t, std::vector<double>> rangeRatiosLastLap;
	size_t withPredictedCovariance = 0;  //!< measurements with a positive finite relPoseCov diagonal
};

/** `odometrySigma`: the odometry the front-end gets is the true path plus
 * a random walk of this many m/sqrt(m) (0: exact). `odometryJumpFrame`:
 * from that image on, the odometry is 1 m to the left of that. */
LapsResult driveLaps(const CVisualFrontEnd::TOptions& options, double laps, double blackoutAfterLaps = 1e9,
	double odometrySigma = 0, int odometryJumpFrame = -1)
{
	vslam::testing::RoomRenderer room(5.0, 4.0, 2.5, 42);
	mrpt::img::TCamera cam;
	cam.ncols = 320;
	cam.nrows = 240;
	cam.setIntrinsicParamsFromValues(250, 250, 160, 120);
	const mrpt::poses::CPose3D mount(0.1, 0, 0.3, -90 * kDeg, 0, -90 * kDeg);
	CVisualFrontEnd fe(options);
	std::map<int64_t, mrpt::poses::CPose2D> frameOf;
	LapsResult run;
	const double radius = 1.0, step = 0.075;  // 0.15 m/s at 2 Hz
	const int frames = static_cast<int>(laps * 2 * M_PI * radius / step);
	std::mt19937 rng(7);
	std::normal_distribution<double> unit(0, 1);
	mrpt::poses::CPose2D previous, odometry;
	for (int k = 0; k < frames; k++)
	{
		const double a = k * step / radius;
		const mrpt::poses::CPose2D robot(2.5 + radius * std::cos(a), 2.0 + radius * std::sin(a), a + M_PI / 2);
		const double noise = odometrySigma * std::sqrt(step);
		odometry = k == 0 ? robot
						  : odometry + (robot - previous) + mrpt::poses::CPose2D(noise * unit(rng), noise * unit(rng), 0);
		if (k == odometryJumpFrame) odometry = odometry + mrpt::poses::CPose2D(0, 1, 0);
		previous = robot;
		mrpt::obs::CObservationImage obs;
		obs.timestamp = mrpt::Clock::fromDouble(1e9 + 0.5 * k);
		obs.sensorLabel = "CAMERA";
		obs.cameraParams = cam;
		obs.cameraPose = mount;
		const bool blackout = k * step / (2 * M_PI * radius) >= blackoutAfterLaps;
		const cv::Mat img = blackout ? cv::Mat(cam.nrows, cam.ncols, CV_8UC1, cv::Scalar(0))
									 : room.render(cam, mrpt::poses::CPose3D(robot) + mount);
		obs.image = mrpt::img::CImage(img, mrpt::img::DEEP_COPY);
		const auto out = fe.process(obs, odometry, "frame " + std::to_string(k));
		run.images++;
		run.pruned += out.pruned.size();
		for (const auto& c : out.created)
		{
			frameOf[c->landmarkID] = robot;
			run.created++;
			run.rows.push_back("C " + std::to_string(k) + " " + c->exportTxtDataRow());
		}
		for (const auto& m : out.measurements)
		{
			run.rows.push_back("M " + std::to_string(k) + " " + m->exportTxtDataRow());
			const mrpt::poses::CPose2D truth = frameOf.at(m->landmarkID) - robot;
			const Eigen::Vector3d error(m->relPose.x() - truth.x(), m->relPose.y() - truth.y(),
				mrpt::math::wrapToPi(m->relPose.phi() - truth.phi()));
			run.translationErrors.push_back(error.head<2>().norm());
			run.headingErrors.push_back(std::abs(error[2]));
			run.predictedMahalanobis2.push_back(error.dot(m->relPoseCov.asEigen().ldlt().solve(error)));
			const auto d = m->relPoseCov.asEigen().diagonal();
			if (d.allFinite() && (d.array() > 0).all()) run.withPredictedCovariance++;
			if (k >= frames - static_cast<int>(2 * M_PI * radius / step) && truth.norm() > 0.5)
				run.rangeRatiosLastLap[m->landmarkID].push_back(m->relPose.norm() / truth.norm());
		}
	}
	run.landmarksInDatabase = fe.database().size();
	run.inconsistent = fe.inconsistentRecognitions();
	return run;
}

double median(std::vector<double> v)
{
	std::sort(v.begin(), v.end());
	return v.empty() ? 1e9 : v[v.size() / 2];
}

/** Two laps: landmarks built on the first, recognized on the second, and
 * no false recognitions: every measurement is near the truth (the worst,
 * ~0.13 m and ~3 deg, have 13-25 inliers at the edge of a landmark's reach). */
void expectTruePosesOnTheSecondLap(const LapsResult& run)
{
	EXPECT_GE(run.created, 4u);
	EXPECT_GE(run.translationErrors.size(), run.images / 2) << "recognitions";
	EXPECT_LT(median(run.translationErrors), 0.03);
	EXPECT_LT(median(run.headingErrors), 0.5 * kDeg);
	EXPECT_LT(*std::max_element(run.translationErrors.begin(), run.translationErrors.end()), 0.3);
	EXPECT_LT(*std::max_element(run.headingErrors.begin(), run.headingErrors.end()), 5 * kDeg);
}

/** The front-end in its plain form: SIFT on the raw image, every inlier
 * weighted alike (config_ini/paper.ini). */
CVisualFrontEnd::TOptions plainFrontEnd()
{
	CVisualFrontEnd::TOptions o;
	o.features.sift_denoise_sigma = 0;
	o.recognition.structure_weighted = false;
	return o;
}
}  // namespace

TEST(CVisualFrontEnd, CreatesOnTheFirstLapRecognizesOnTheSecondWithTheTruePose)
{
	const LapsResult run = driveLaps(plainFrontEnd(), 2);
	expectTruePosesOnTheSecondLap(run);
	EXPECT_EQ(run.withPredictedCovariance, run.translationErrors.size());
}

TEST(CVisualFrontEnd, WithTheDefaultsAFarMeasurementSaysItIsUncertain)
{
	// Denoised SIFT and structure-weighted poses (the defaults) measure as
	// well, but one measurement from 14 inliers at the edge of a landmark's
	// reach is 0.43 m and 8.5 deg off; its own predicted covariance gives it
	// 0.57 m. The filter takes each prediction times predicted_cov_scale = 4
	// (in std); every error lies well inside that (measured: at most 5.6
	// times the predicted std, 1.4 times the scaled one).
	const LapsResult run = driveLaps(CVisualFrontEnd::TOptions(), 2);
	EXPECT_GE(run.created, 4u);
	EXPECT_GE(run.translationErrors.size(), run.images / 2) << "recognitions";
	EXPECT_LT(median(run.translationErrors), 0.03);
	EXPECT_LT(median(run.headingErrors), 0.5 * kDeg);
	ASSERT_EQ(run.withPredictedCovariance, run.translationErrors.size());
	size_t far = 0;
	for (size_t i = 0; i < run.translationErrors.size(); i++)
		if (run.translationErrors[i] > 0.3 || run.headingErrors[i] > 5 * kDeg) far++;
	EXPECT_LE(far, run.translationErrors.size() / 100) << "measurements beyond 0.3 m or 5 deg";
	const double chi2_3dof_999 = 16.27, scale = 4;
	EXPECT_LT(*std::max_element(run.predictedMahalanobis2.begin(), run.predictedMahalanobis2.end()),
		chi2_3dof_999 * scale * scale);
}

TEST(CVisualFrontEnd, WithSiftOnTheHalfImageStillRecognizesWithTheTruePose)
{
	// SIFT on the image halved finds fewer features at 320x240 (no octave
	// on the doubled full image); the room's texture is coarse enough for it.
	CVisualFrontEnd::TOptions options;
	options.features.sift_max_cols = 160;
	expectTruePosesOnTheSecondLap(driveLaps(options, 2));
}

/** How far the landmarks' scales are off in the last lap: the median over
 * landmarks of |median range ratio - 1|. */
double medianScaleError(const LapsResult& run)
{
	std::vector<double> perLandmark;
	for (const auto& [id, ratios] : run.rangeRatiosLastLap)
		if (ratios.size() >= 3) perLandmark.push_back(std::abs(median(ratios) - 1));
	return median(perLandmark);
}

/** Median scale errors of the landmarks of three laps on noisy odometry
 * (the paper's sigma_T: each landmark's 0.3 m creation baseline gives it a
 * scale error of several percent), as built and with the scale track. */
std::pair<double, double> scaleErrorsAsBuiltAndRefined(CVisualFrontEnd::TOptions o)
{
	o.scale.enabled = false;
	const LapsResult asBuilt = driveLaps(o, 3, 1e9, 0.05);
	o.scale.enabled = true;
	const LapsResult refined = driveLaps(o, 3, 1e9, 0.05);
	EXPECT_GE(asBuilt.rangeRatiosLastLap.size(), 4u);
	EXPECT_GE(refined.rangeRatiosLastLap.size(), 4u);
	std::cout << "median landmark scale error: as built " << medianScaleError(asBuilt) << ", refined "
			  << medianScaleError(refined) << "\n";
	return {medianScaleError(asBuilt), medianScaleError(refined)};
}

TEST(CVisualFrontEnd, LaterSightingsCorrectTheScaleOfLandmarksBuiltOnNoisyOdometry)
{
	// The sightings of two more laps, against the same noisy odometry,
	// bring the scale error down.
	const auto [asBuilt, refined] = scaleErrorsAsBuiltAndRefined(plainFrontEnd());
	EXPECT_LT(refined, 0.6 * asBuilt);
	EXPECT_LT(refined, 0.045);  // measured 0.039 (as built 0.095)
	// Structure-weighted poses (the default) refine less here: measured
	// 0.050 (as built 0.091), 0.040 without them.
	const auto [asBuiltWeighted, refinedWeighted] = scaleErrorsAsBuiltAndRefined(CVisualFrontEnd::TOptions());
	EXPECT_LT(refinedWeighted, 0.6 * asBuiltWeighted);
	EXPECT_LT(refinedWeighted, 0.06);
}

/** The measurement rows ("M k ...") of images k in [from, to). */
std::vector<std::string> measurementRows(const LapsResult& run, int from, int to)
{
	std::vector<std::string> rows;
	for (const auto& r : run.rows)
	{
		const int k = std::stoi(r.substr(2));
		if (r[0] == 'M' && k >= from && k < to) rows.push_back(r);
	}
	return rows;
}

TEST(CVisualFrontEnd, ARecognitionTheOdometryRulesOutCountsAsRecognizedButIsNotReported)
{
	// A third into the second lap the odometry jumps 1 m to the left (as a
	// wrong recognition would look against right odometry). The gate drops
	// the recognitions of landmarks recognized in the 5 s (10 images) before
	// the jump, and only those: before it (exact odometry) and once 5 s have
	// passed, the outputs are those without the gate; and no landmark is built
	// for the dropped ones. (The scale track is off: it would take the jump
	// for a scale error.)
	CVisualFrontEnd::TOptions o;
	o.scale.enabled = false;
	const int jump = 110, afterHorizon = jump + 11;  // of about 168 images
	o.recognition.odometry_gate.horizon = 0;
	const LapsResult ungated = driveLaps(o, 2, 1e9, 0, jump);
	o.recognition.odometry_gate.horizon = 5;
	const LapsResult gated = driveLaps(o, 2, 1e9, 0, jump);
	std::cout << "recognitions dropped after the odometry's jump: " << gated.inconsistent << " of "
			  << measurementRows(ungated, jump, afterHorizon).size() << "\n";
	EXPECT_EQ(ungated.inconsistent, 0u);
	EXPECT_GE(measurementRows(ungated, 0, jump).size(), 20u);
	EXPECT_EQ(measurementRows(gated, 0, jump), measurementRows(ungated, 0, jump));
	EXPECT_GE(gated.inconsistent, 5u);
	EXPECT_EQ(measurementRows(gated, jump, afterHorizon).size() + gated.inconsistent,
		measurementRows(ungated, jump, afterHorizon).size());
	EXPECT_GE(measurementRows(ungated, afterHorizon, 1000).size(), 10u);
	EXPECT_EQ(measurementRows(gated, afterHorizon, 1000), measurementRows(ungated, afterHorizon, 1000));
	EXPECT_EQ(gated.created, ungated.created);
}

TEST(CVisualFrontEnd, SameImagesSameOutputs)
{
	const auto first = driveLaps(CVisualFrontEnd::TOptions(), 1);
	EXPECT_GT(first.rows.size(), 10u);
	EXPECT_EQ(first.rows, driveLaps(CVisualFrontEnd::TOptions(), 1).rows);
}

TEST(CVisualFrontEnd, TheLandmarkCapBoundsTheMap)
{
	CVisualFrontEnd::TOptions o;
	o.database.max_landmarks = 3;
	const LapsResult run = driveLaps(o, 1);
	EXPECT_LE(run.landmarksInDatabase, 3u);
	EXPECT_GT(run.created, 3u);
}

TEST(CVisualFrontEnd, LandmarksExpectedButNotSeenArePruned)
{
	// A camera blackout on the second lap: every landmark is expected where
	// it was made and missed there, so with prune_after_misses = 2 all go;
	// without pruning they all stay.
	CVisualFrontEnd::TOptions o;
	const LapsResult kept = driveLaps(o, 1.9, 1.0);
	EXPECT_GE(kept.created, 4u);
	EXPECT_EQ(kept.pruned, 0u);
	EXPECT_EQ(kept.landmarksInDatabase, kept.created);
	o.database.prune_after_misses = 2;
	const LapsResult pruned = driveLaps(o, 1.9, 1.0);
	EXPECT_EQ(pruned.created, kept.created);
	EXPECT_EQ(pruned.landmarksInDatabase + pruned.pruned, pruned.created);
	EXPECT_GE(pruned.pruned, pruned.created - 1);
}

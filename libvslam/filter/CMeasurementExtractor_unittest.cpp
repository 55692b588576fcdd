#include <gtest/gtest.h>
#include <libvslam/core/InputError.h>
#include <libvslam/filter/CMeasurementExtractor.h>
#include <libvslam/obs/CObservationHeadingChange.h>
#include <libvslam/obs/CObservationLandmarkCreated.h>
#include <libvslam/obs/CObservationVisualLandmark.h>
#include <mrpt/obs/CObservationBearingRange.h>

#include <cmath>
#include <limits>

using namespace vslam;

namespace
{
CObservationVisualLandmark::Ptr visual(int64_t id, double projErr, uint32_t n)
{
	auto o = CObservationVisualLandmark::Create();
	o->landmarkID = id;
	o->relPose = mrpt::poses::CPose2D(1.0, 0.5, 0.2);
	o->ProjErrRMS = projErr;
	o->NPoints = n;
	return o;
}

CObservationHeadingChange::Ptr headingChange(double t0, double t1, double dphi, double std)
{
	auto o = CObservationHeadingChange::Create();
	o->previousTimestamp = mrpt::Clock::fromDouble(t0);
	o->timestamp = mrpt::Clock::fromDouble(t1);
	o->dphi = dphi;
	o->stdDphi = std;
	return o;
}

mrpt::obs::CObservationBearingRange::Ptr bearingRange()
{
	auto o = mrpt::obs::CObservationBearingRange::Create();
	o->sensorLocationOnRobot = mrpt::poses::CPose3D(0.1, 0, 0.3, 0.05, 0, 0);
	o->sensor_std_range = 0.1f;
	o->sensor_std_yaw = 0.01f;
	for (int32_t id : {7, -1, 8, 9})
	{
		mrpt::obs::CObservationBearingRange::TMeasurement m;
		m.range = id == 8 ? 20.f : id == 9 ? 0.f : 2.f;  // 9: a range of 0 has no bearing
		m.yaw = 0.3f;
		m.pitch = 0;
		m.landmarkID = id;
		o->sensedData.push_back(m);
	}
	return o;
}
}  // namespace

TEST(CMeasurementExtractor, VisualMeasurementsGoThroughThePreFilter)
{
	CMeasurementExtractor ex;
	mrpt::obs::CSensoryFrame sf;
	sf.insert(visual(1, 1.0, 40));
	sf.insert(visual(2, 4.0, 40));  // ProjErrRMS too large
	sf.insert(visual(3, 1.0, 3));  // too few points
	auto c = CObservationLandmarkCreated::Create();
	c->landmarkID = 9;
	sf.insert(c);
	const FrameMeasurements f = ex.extract(sf);
	ASSERT_EQ(f.measurements.size(), 1u);
	EXPECT_EQ(f.measurements[0].key.id, 1);
	EXPECT_EQ(f.measurements[0].kind(), LandmarkKind::Pose);
	EXPECT_NEAR(f.measurements[0].z[1], 0.5, 1e-12);
	EXPECT_NEAR(f.measurements[0].R(0, 0), 0.09 * 0.09, 1e-12);
	EXPECT_NEAR(f.measurements[0].R(2, 2), 0.0019, 1e-9);  // paper's Sigma_vis
	ASSERT_EQ(f.creations.size(), 1u);
	EXPECT_EQ(f.creations[0].key.id, 9);
	EXPECT_EQ(ex.stats().visualSeen, 3u);
	EXPECT_EQ(ex.stats().rejectedProjErrRMS, 1u);
	EXPECT_EQ(ex.stats().rejectedNPoints, 1u);
}

TEST(CMeasurementExtractor, RangeBearingWithIdsSensorPoseAndLimits)
{
	CMeasurementExtractor ex;
	ex.rangeBearing.max_range = 10;
	mrpt::obs::CSensoryFrame sf;
	sf.insert(bearingRange());
	const FrameMeasurements f = ex.extract(sf);
	ASSERT_EQ(f.measurements.size(), 1u);
	const auto& m = f.measurements[0];
	EXPECT_EQ(m.key.id, 7);
	EXPECT_EQ(m.kind(), LandmarkKind::Point);
	EXPECT_NEAR(m.sensorPose.x, 0.1, 1e-12);
	EXPECT_NEAR(m.sensorPose.phi, 0.05, 1e-9);
	EXPECT_NEAR(m.R(0, 0), 0.01, 1e-7);  // from the observation
	EXPECT_EQ(ex.stats().rejectedNoLandmarkID, 1u);
	EXPECT_EQ(ex.stats().rejectedRangeLimits, 2u);
	ex.rangeBearing.std_range = 0.5;  // the INI overrides the observation
	EXPECT_NEAR(ex.extract(sf).measurements[0].R(0, 0), 0.25, 1e-12);
}

TEST(CMeasurementExtractor, PredictedCovarianceScaledAddsToSigmaVisOnlyWhenAsked)
{
	auto v = visual(1, 1.0, 40);
	v->relPoseCov(0, 0) = 0.01;
	v->relPoseCov(1, 1) = 0.04;
	v->relPoseCov(0, 1) = v->relPoseCov(1, 0) = 0.005;
	v->relPoseCov(2, 2) = 1e-4;
	mrpt::obs::CSensoryFrame sf;
	sf.insert(v);
	sf.insert(visual(2, 1.0, 40));  // no prediction (all zero): Sigma_vis alone

	CMeasurementExtractor paper;
	paper.visual.predicted_cov_scale = 0;
	const auto fixed = paper.extract(sf).measurements;
	ASSERT_EQ(fixed.size(), 2u);
	EXPECT_NEAR(fixed[0].R(1, 1), 0.09 * 0.09, 1e-12);
	EXPECT_EQ(fixed[0].R(0, 1), 0);

	CMeasurementExtractor scaled;
	scaled.visual.predicted_cov_scale = 3;
	const auto m = scaled.extract(sf).measurements;
	ASSERT_EQ(m.size(), 2u);
	EXPECT_NEAR(m[0].R(0, 0), 0.09 * 0.09 + 9 * 0.01, 1e-12);
	EXPECT_NEAR(m[0].R(1, 1), 0.09 * 0.09 + 9 * 0.04, 1e-12);
	EXPECT_NEAR(m[0].R(0, 1), 9 * 0.005, 1e-12);
	EXPECT_NEAR(m[0].R(1, 0), 9 * 0.005, 1e-12);
	EXPECT_NEAR(m[0].R(2, 2), 0.0019 + 9e-4, 1e-9);
	EXPECT_EQ(m[1].R, fixed[1].R);

	v->relPoseCov(2, 2) = std::numeric_limits<double>::infinity();
	EXPECT_THROW(scaled.extract(sf), InputError);
	v->relPoseCov(2, 2) = -1e-4;
	EXPECT_THROW(scaled.extract(sf), InputError);
}

TEST(CMeasurementExtractor, NonFiniteInputIsAnInputError)
{
	CMeasurementExtractor ex;
	mrpt::obs::CSensoryFrame sf;
	auto v = visual(1, 1.0, 40);
	v->relPose = mrpt::poses::CPose2D(std::nan(""), 0, 0);
	sf.insert(v);
	EXPECT_THROW(ex.extract(sf), InputError);

	mrpt::obs::CSensoryFrame sf2;
	auto br = bearingRange();
	br->sensedData[0].range = std::numeric_limits<float>::infinity();
	sf2.insert(br);
	EXPECT_THROW(ex.extract(sf2), InputError);
}

TEST(CMeasurementExtractor, RangeBearingWithoutAnyNoiseFigureIsAnError)
{
	CMeasurementExtractor ex;
	mrpt::obs::CSensoryFrame sf;
	auto br = bearingRange();
	br->sensor_std_range = 0;
	sf.insert(br);
	try
	{
		ex.extract(sf);
		FAIL();
	}
	catch (const InputError& e)
	{
		EXPECT_NE(std::string(e.what()).find("std_range"), std::string::npos);
	}
}

// Found by fuzz_rawlog: a sensor pose of NaN made every particle's weight
// NaN, and MRPT's resampling then failed an assertion.
TEST(CMeasurementExtractor, ImpossibleRangeBearingValuesAreInputErrors)
{
	const auto expectError = [](const mrpt::obs::CObservationBearingRange::Ptr& br, const char* part) {
		CMeasurementExtractor ex;
		mrpt::obs::CSensoryFrame sf;
		sf.insert(br);
		try
		{
			ex.extract(sf);
			ADD_FAILURE() << "no error for " << part;
		}
		catch (const InputError& e)
		{
			EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
		}
	};
	auto nanPose = bearingRange();
	nanPose->sensorLocationOnRobot = mrpt::poses::CPose3D(std::nan(""), 0, 0, 0, 0, 0);
	expectError(nanPose, "sensor pose");
	auto farPose = bearingRange();
	farPose->sensorLocationOnRobot = mrpt::poses::CPose3D(1e9, 0, 0, 0, 0, 0);
	expectError(farPose, "sensor pose");
	auto hugeNoise = bearingRange();
	hugeNoise->sensor_std_range = 1e30f;
	expectError(hugeNoise, "beyond any sensor");
	auto hugeRange = bearingRange();
	hugeRange->sensedData[0].range = 1e20f;
	expectError(hugeRange, "beyond any sensor");
}

TEST(CMeasurementExtractor, HeadingChangesPassOnlyWhenEnabledWithTheirNoise)
{
	CMeasurementExtractor ex;
	EXPECT_TRUE(ex.headingChange.enabled);  // on by default (the camera configuration)
	ex.headingChange.enabled = false;  // the paper's filter
	mrpt::obs::CSensoryFrame sf;
	sf.insert(headingChange(10.0, 10.4, 0.05, 1e-3));
	FrameMeasurements f = ex.extract(sf);
	EXPECT_FALSE(f.headingChange);
	EXPECT_TRUE(f.empty());
	EXPECT_EQ(ex.stats().headingChangesSeen, 1u);
	EXPECT_EQ(ex.stats().headingChangesPassed, 0u);

	ex.headingChange.enabled = true;
	f = ex.extract(sf);
	ASSERT_TRUE(f.headingChange);
	EXPECT_TRUE(f.empty());  // no landmark measurement: the filter only corrects its odometry
	EXPECT_EQ(f.headingChange->from, mrpt::Clock::fromDouble(10.0));
	EXPECT_EQ(f.headingChange->to, mrpt::Clock::fromDouble(10.4));
	EXPECT_EQ(f.headingChange->dphi, 0.05);
	constexpr double kMin = decltype(ex.headingChange)::kMinStd;
	EXPECT_NEAR(f.headingChange->variance, 1e-6 + kMin * kMin, 1e-18);

	// Two cameras: the more precise one.
	sf.insert(headingChange(10.1, 10.4, 0.06, 5e-4));
	f = ex.extract(sf);
	ASSERT_TRUE(f.headingChange);
	EXPECT_EQ(f.headingChange->dphi, 0.06);
	EXPECT_EQ(ex.stats().headingChangesPassed, 2u);
}

TEST(CMeasurementExtractor, CorruptHeadingChangesAreInputErrors)
{
	CMeasurementExtractor ex;
	for (const auto& h : {headingChange(1, 2, std::nan(""), 1e-3), headingChange(1, 2, 0.1, -1e-3),
			 headingChange(1, 2, 0.1, std::numeric_limits<double>::infinity()), headingChange(2, 2, 0.1, 1e-3)})
	{
		mrpt::obs::CSensoryFrame sf;
		sf.insert(h);
		EXPECT_THROW(ex.extract(sf), InputError);
	}
}

#include <gtest/gtest.h>
#include <libvslam/obs/CObservationLandmarkCreated.h>
#include <libvslam/obs/CObservationVisualLandmark.h>
#include <libvslam/sim/CMeasurementSimulator.h>
#include <mrpt/obs/CObservationBearingRange.h>

using namespace vslam;

namespace
{
CMeasurementSimulator::TOptions quiet()
{
	CMeasurementSimulator::TOptions o;
	o.duration = 200;
	o.bad_measurement_probability = 0;
	o.landmark_frame_std_xy = 0;
	o.landmark_frame_std_phi = 0;
	return o;
}
}  // namespace

TEST(CMeasurementSimulator, SameSeedSameRun)
{
	auto o = quiet();
	const auto a = CMeasurementSimulator(o).run();
	const auto b = CMeasurementSimulator(o).run();
	ASSERT_EQ(a.steps.size(), b.steps.size());
	for (size_t i = 0; i < a.steps.size(); i++)
	{
		EXPECT_EQ(a.steps[i].truePose.x, b.steps[i].truePose.x);
		EXPECT_EQ(a.steps[i].odometryIncrement.phi, b.steps[i].odometryIncrement.phi);
		EXPECT_EQ(a.steps[i].sf->size(), b.steps[i].sf->size());
	}
	o.seed = 2;
	const auto c = CMeasurementSimulator(o).run();
	EXPECT_NE(a.steps.back().truePose.x, c.steps.back().truePose.x);
}

TEST(CMeasurementSimulator, VisualMeasurementsHaveTheConfiguredNoise)
{
	auto o = quiet();
	o.duration = 600;
	const auto run = CMeasurementSimulator(o).run();
	std::map<int64_t, se2::Pose> frames;
	for (const auto& l : run.landmarks) frames[l.key.id] = l.pose;
	double sx = 0, sphi = 0;
	size_t n = 0, created = 0;
	for (const auto& st : run.steps)
		for (const auto& obs : *st.sf)
		{
			if (std::dynamic_pointer_cast<CObservationLandmarkCreated>(obs)) created++;
			const auto m = std::dynamic_pointer_cast<CObservationVisualLandmark>(obs);
			if (!m) continue;
			const se2::Pose truth = se2::between(st.truePose, frames.at(m->landmarkID));
			const Eigen::Vector3d e = se2::difference(m->relPose.asTPose(), truth);
			sx += e[0] * e[0];
			sphi += e[2] * e[2];
			n++;
			EXPECT_LE(m->ProjErrRMS, 3.0);
		}
	EXPECT_GT(n, 200u);
	EXPECT_EQ(created, run.creations);
	EXPECT_NEAR(std::sqrt(sx / n), o.meas_std_dx, 0.15 * o.meas_std_dx);
	EXPECT_NEAR(std::sqrt(sphi / n), o.meas_std_dphi, 0.15 * o.meas_std_dphi);
}

TEST(CMeasurementSimulator, OdometryNoiseMatchesTheModel)
{
	auto o = quiet();
	o.duration = 2000;
	o.odo_scale_bias = 0.02;
	const auto run = CMeasurementSimulator(o).run();
	// Forward error divided by sqrt(distance) has std sigma_T, and the
	// mean relative error is the scale bias.
	double sum = 0, sum2 = 0, rel = 0, dist = 0;
	size_t n = 0;
	se2::Pose prev = run.steps[0].truePose;
	for (size_t i = 1; i < run.steps.size(); i++)
	{
		const se2::Pose truth = se2::between(prev, run.steps[i].truePose);
		prev = run.steps[i].truePose;
		if (truth.x < 1e-3) continue;
		const double e = run.steps[i].odometryIncrement.x - truth.x * (1 + o.odo_scale_bias);
		sum += e / std::sqrt(truth.x);
		sum2 += e * e / truth.x;
		rel += run.steps[i].odometryIncrement.x - truth.x;
		dist += truth.x;
		n++;
	}
	ASSERT_GT(n, 1000u);
	EXPECT_NEAR(std::sqrt(sum2 / n - (sum / n) * (sum / n)), o.odo_sigma_T, 0.1 * o.odo_sigma_T);
	EXPECT_NEAR(rel / dist, o.odo_scale_bias, 0.01);
}

TEST(CMeasurementSimulator, RangeBearingRespectsFieldOfViewAndRange)
{
	auto o = quiet();
	o.landmark_type = CMeasurementSimulator::TOptions::LandmarkType::RangeBearing;
	const auto run = CMeasurementSimulator(o).run();
	EXPECT_GT(run.rangeBearingMeasurements, 100u);
	for (const auto& st : run.steps)
		for (const auto& obs : *st.sf)
		{
			const auto br = std::dynamic_pointer_cast<mrpt::obs::CObservationBearingRange>(obs);
			ASSERT_TRUE(br);
			for (const auto& m : br->sensedData)
			{
				EXPECT_LE(m.range, o.rb_max_range + 5 * o.rb_std_range);
				EXPECT_LE(std::abs(m.yaw), o.rb_fov / 2 + 5 * o.rb_std_bearing);
			}
		}
}

TEST(CMeasurementSimulator, KidnapMovesTheRobotFarWithoutOdometrySeeingIt)
{
	auto o = quiet();
	o.kidnap_times = {100};
	const auto run = CMeasurementSimulator(o).run();
	size_t kidnaps = 0;
	for (size_t i = 1; i < run.steps.size(); i++)
		if (run.steps[i].kidnappedHere)
		{
			kidnaps++;
			const auto& a = run.steps[i - 1].truePose;
			const auto& b = run.steps[i].truePose;
			EXPECT_GE(std::hypot(a.x - b.x, a.y - b.y), o.kidnap_min_distance - 0.2);
			EXPECT_LT(std::abs(run.steps[i].odometryIncrement.x), 0.1);
		}
	EXPECT_EQ(kidnaps, 1u);
}

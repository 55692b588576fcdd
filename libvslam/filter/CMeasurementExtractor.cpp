#include <libvslam/config/StrictRead.h>
#include <libvslam/core/InputError.h>
#include <libvslam/filter/CMeasurementExtractor.h>
#include <libvslam/obs/CObservationHeadingChange.h>
#include <libvslam/obs/CObservationLandmarkCreated.h>
#include <libvslam/obs/CObservationVisualLandmark.h>
#include <mrpt/obs/CObservationBearingRange.h>

#include <cmath>

using namespace vslam;
using namespace vslam::config;

void CMeasurementExtractor::TVisualOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	std_dx = readDouble(c, s, "std_dx", std_dx, Range{0, 100, false, true});
	std_dy = readDouble(c, s, "std_dy", std_dy, Range{0, 100, false, true});
	std_dphi = readDegreesAsRadians(c, s, "std_dphi_deg", std_dphi, Range{0, 360, false, true});
	predicted_cov_scale =
		readDouble(c, s, "predicted_cov_scale", predicted_cov_scale, Range::closed(0, 100));
}

void CMeasurementExtractor::TVisualOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "std_dx", std_dx, 25, 12, "Visual measurement noise, dx [m] (paper: 0.09)");
	c.write(s, "std_dy", std_dy, 25, 12, "Visual measurement noise, dy [m] (paper: 0.09)");
	c.write(s, "std_dphi_deg", std_dphi * 180 / M_PI, 25, 12,
		"Visual measurement noise, dtheta [deg] (paper: 0.0019 rad^2 = 2.4975 deg)");
	c.write(s, "predicted_cov_scale", predicted_cov_scale, 25, 12,
		"Add this factor^2 x each measurement's predicted covariance to Sigma_vis (0: Sigma_vis alone, the paper)");
}

void CMeasurementExtractor::TRangeBearingOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	std_range = readDouble(c, s, "std_range", std_range, Range::closed(0, 1000));
	std_bearing = readDegreesAsRadians(
		c, s, "std_bearing_deg", std_bearing, Range::closed(0, 180));
	min_range = readDouble(c, s, "min_range", min_range, Range::nonNegative());
	max_range = readDouble(c, s, "max_range", max_range, Range::nonNegative());
}

void CMeasurementExtractor::TRangeBearingOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "std_range", std_range, 25, 12,
		"Range noise [m]; 0: each observation's sensor_std_range");
	c.write(s, "std_bearing_deg", std_bearing * 180 / M_PI, 25, 12,
		"Bearing noise [deg]; 0: each observation's sensor_std_yaw");
	c.write(s, "min_range", min_range, 25, 12, "Ignore ranges below this [m] (a range of 0 always)");
	c.write(s, "max_range", max_range, 25, 12, "Ignore ranges above this [m] (0: no limit)");
}

void CMeasurementExtractor::THeadingChangeOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	enabled = readBool(c, s, "enabled", enabled);
	gate_probability = readDouble(c, s, "gate_probability", gate_probability, {0, 1, false, false});
}

void CMeasurementExtractor::THeadingChangeOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "enabled", enabled, 25, 12,
		"Fuse the front-end's heading changes between images into the odometry (not in the paper)");
	c.write(s, "gate_probability", gate_probability, 25, 12,
		"Chi-square gate against the odometry: a heading change outside it is not used");
}

namespace
{
bool finite(const mrpt::poses::CPose2D& p)
{
	return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.phi());
}

se2::Pose planar(const mrpt::poses::CPose3D& p) { return {p.x(), p.y(), p.yaw()}; }
}  // namespace

FrameMeasurements CMeasurementExtractor::extract(const mrpt::obs::CSensoryFrame& sf)
{
	FrameMeasurements out;
	bool haveTime = false;
	for (const auto& obs : sf)
	{
		if (!obs) continue;
		if (!haveTime)
		{
			out.timestamp = obs->timestamp;
			haveTime = true;
		}
		if (auto v = std::dynamic_pointer_cast<CObservationVisualLandmark>(obs))
			addVisual(*v, out);
		else if (auto c = std::dynamic_pointer_cast<CObservationLandmarkCreated>(obs))
			addCreation(*c, out);
		else if (auto h = std::dynamic_pointer_cast<CObservationHeadingChange>(obs))
			addHeadingChange(*h, out);
		else if (auto br = std::dynamic_pointer_cast<mrpt::obs::CObservationBearingRange>(obs))
			addRangeBearing(*br, out);
	}
	return out;
}

void CMeasurementExtractor::addVisual(const CObservationVisualLandmark& v, FrameMeasurements& out)
{
	m_stats.visualSeen++;
	if (!finite(v.relPose))
		throw InputError("visual measurement of landmark " + std::to_string(v.landmarkID) + " has a non-finite pose");
	switch (preFilter.check(v))
	{
		case CPreFilter::Verdict::RejectedProjErrRMS:
			m_stats.rejectedProjErrRMS++;
			return;
		case CPreFilter::Verdict::RejectedNPoints:
			m_stats.rejectedNPoints++;
			return;
		case CPreFilter::Verdict::RejectedSlope:
			m_stats.rejectedSlope++;
			return;
		case CPreFilter::Verdict::Accepted:
			break;
	}
	m_stats.visualAccepted++;
	LandmarkMeasurement m;
	m.key = {LandmarkKind::Pose, v.landmarkID};
	m.z.resize(3);
	m.z << v.relPose.x(), v.relPose.y(), v.relPose.phi();
	m.R = MatN::Zero(3, 3);
	m.R.diagonal() << visual.std_dx * visual.std_dx, visual.std_dy * visual.std_dy, visual.std_dphi * visual.std_dphi;
	if (visual.predicted_cov_scale > 0)
	{
		const auto& P = v.relPoseCov.asEigen();
		if (!P.allFinite() || (P.diagonal().array() < 0).any())
			throw InputError("visual measurement of landmark " + std::to_string(v.landmarkID) +
				" has a predicted covariance that is not finite or has a negative variance");
		m.R += visual.predicted_cov_scale * visual.predicted_cov_scale * P;
	}
	out.measurements.push_back(std::move(m));
}

void CMeasurementExtractor::addCreation(const CObservationLandmarkCreated& c, FrameMeasurements& out)
{
	m_stats.creationsSeen++;
	if (!finite(c.landmarkPoseInRobot) || !c.landmarkPoseInRobotCov.asEigen().allFinite())
		throw InputError("creation of landmark " + std::to_string(c.landmarkID) + " has a non-finite pose");
	LandmarkCreation lc;
	lc.key = {LandmarkKind::Pose, c.landmarkID};
	lc.relative.key = lc.key;
	lc.relative.z.resize(3);
	lc.relative.z << c.landmarkPoseInRobot.x(), c.landmarkPoseInRobot.y(), c.landmarkPoseInRobot.phi();
	lc.relative.R = c.landmarkPoseInRobotCov.asEigen();
	out.creations.push_back(std::move(lc));
}

void CMeasurementExtractor::addHeadingChange(const CObservationHeadingChange& h, FrameMeasurements& out)
{
	m_stats.headingChangesSeen++;
	if (!std::isfinite(h.dphi) || !std::isfinite(h.stdDphi) || h.stdDphi < 0)
		throw InputError("heading change of '" + h.sensorLabel + "' is not finite or has a negative std");
	if (!(h.previousTimestamp < h.timestamp))
		throw InputError("heading change of '" + h.sensorLabel + "' starts at " +
			std::to_string(mrpt::Clock::toDouble(h.previousTimestamp)) + ", not before its own time " +
			std::to_string(mrpt::Clock::toDouble(h.timestamp)));
	if (!headingChange.enabled) return;
	constexpr double kMinStd = THeadingChangeOptions::kMinStd;
	const HeadingChangeMeasurement m{
		h.previousTimestamp, h.timestamp, h.dphi, h.stdDphi * h.stdDphi + kMinStd * kMinStd};
	if (!out.headingChange)
		m_stats.headingChangesPassed++;
	else if (out.headingChange->variance <= m.variance)
		return;
	out.headingChange = m;
}

void CMeasurementExtractor::addRangeBearing(const mrpt::obs::CObservationBearingRange& br, FrameMeasurements& out)
{
	const double stdR = rangeBearing.std_range > 0 ? rangeBearing.std_range : br.sensor_std_range;
	const double stdB = rangeBearing.std_bearing > 0 ? rangeBearing.std_bearing : br.sensor_std_yaw;
	for (const auto& d : br.sensedData)
	{
		m_stats.rangeBearingSeen++;
		if (!std::isfinite(d.range) || !std::isfinite(d.yaw))
			throw InputError("range-bearing measurement of landmark " + std::to_string(d.landmarkID) + " is not finite");
		if (d.landmarkID < 0)
		{
			m_stats.rejectedNoLandmarkID++;
			continue;
		}
		// A range of 0 (a sensor's "nothing measured") places the point on
		// the sensor with no bearing: never a measurement, whatever min_range.
		if (!(d.range > 0) || d.range < rangeBearing.min_range ||
			(rangeBearing.max_range > 0 && d.range > rangeBearing.max_range))
		{
			m_stats.rejectedRangeLimits++;
			continue;
		}
		if (!(stdR > 0) || !(stdB > 0))
			throw InputError("range-bearing observation '" + br.sensorLabel +
				"' has no noise figure: set [vslam_range_bearing] std_range and std_bearing_deg");
		if (!(stdR < 1e6) || !(stdB <= 2 * M_PI) || !(std::abs(d.range) < 1e6))
			throw InputError("range-bearing observation '" + br.sensorLabel + "': range " + std::to_string(d.range) +
				" m, noise " + std::to_string(stdR) + " m / " + std::to_string(stdB) +
				" rad are beyond any sensor: corrupt data");
		const auto& sp = br.sensorLocationOnRobot;
		if (!std::isfinite(sp.x()) || !std::isfinite(sp.y()) || !std::isfinite(sp.yaw()) || std::abs(sp.x()) > 1e3 ||
			std::abs(sp.y()) > 1e3)
			throw InputError("range-bearing observation '" + br.sensorLabel +
				"': sensor pose on the robot is not finite or is kilometres away: corrupt data");
		m_stats.rangeBearingAccepted++;
		LandmarkMeasurement m;
		m.key = {LandmarkKind::Point, d.landmarkID};
		m.z.resize(2);
		m.z << d.range, d.yaw;
		m.R = MatN::Zero(2, 2);
		m.R.diagonal() << stdR * stdR, stdB * stdB;
		m.sensorPose = planar(br.sensorLocationOnRobot);
		out.measurements.push_back(std::move(m));
	}
}

#include <libvslam/frontend/LandmarkScaleTrack.h>

#include <cmath>
#include <stdexcept>

using namespace vslam;

namespace
{
/** 99% quantile of chi-square with 2 degrees of freedom. */
constexpr double kGate99 = 9.21;
}  // namespace

LandmarkScaleTrack::LandmarkScaleTrack(double creationBaseline, const TScaleRefinementSettings& settings)
	: m_settings(settings)
{
	if (!(creationBaseline > 0) || !(settings.odometrySigma > 0))
		throw std::invalid_argument("LandmarkScaleTrack: baseline and odometry sigma must be positive");
	m_information = creationBaseline / (settings.odometrySigma * settings.odometrySigma);
	m_weightedSum = m_information;
}

double LandmarkScaleTrack::scaleErrorStd() const { return 1 / std::sqrt(m_information); }

double LandmarkScaleTrack::addSighting(const ScaleSighting& s)
{
	if (!std::isfinite(s.stdPosition)) return 1;  // a degenerate solve measures nothing
	// Back to the units the landmark was built in.
	const double applied = appliedFactor();
	ScaleSighting now = s;
	now.cameraInLandmark = s.cameraInLandmark * (1 / applied);
	now.stdPosition = s.stdPosition / applied;
	if (!m_anchor)
	{
		m_anchor = now;
		return 1;
	}
	const double travel = now.travelled - m_anchor->travelled;
	if (travel > m_settings.pairMaxTravel)
	{
		m_anchor = now;
		return 1;
	}
	if (travel < m_settings.pairMinTravel) return 1;

	// The odometry displacement, rotated from the odometry frame into the
	// landmark frame by the anchor's heading in each.
	const double rotation = m_anchor->headingInLandmark - m_anchor->headingInOdometry;
	const auto odometryStep = now.cameraInOdometry - m_anchor->cameraInOdometry;
	const double c = std::cos(rotation), sn = std::sin(rotation);
	const double odoX = c * odometryStep.x - sn * odometryStep.y, odoY = sn * odometryStep.x + c * odometryStep.y;
	const double visX = now.cameraInLandmark.x - m_anchor->cameraInLandmark.x;
	const double visY = now.cameraInLandmark.y - m_anchor->cameraInLandmark.y;

	const double k = scaleError();
	const double variance = m_anchor->stdPosition * m_anchor->stdPosition + now.stdPosition * now.stdPosition +
		k * k * m_settings.odometrySigma * m_settings.odometrySigma * travel;
	const double rx = visX - k * odoX, ry = visY - k * odoY;
	// The gate also allows for the uncertainty of k itself.
	const double gateVariance = variance + (odoX * odoX + odoY * odoY) / m_information;
	m_anchor = now;
	if (!(variance > 0) || (rx * rx + ry * ry) / gateVariance > kGate99 || !std::isfinite(rx + ry))
	{
		m_rejected++;
		return 1;
	}
	const double information = m_information + (odoX * odoX + odoY * odoY) / variance;
	const double weightedSum = m_weightedSum + (visX * odoX + visY * odoY) / variance;
	if (!(weightedSum > 0))
	{
		m_rejected++;
		return 1;
	}
	m_used++;
	m_information = information;
	m_weightedSum = weightedSum;
	return appliedFactor() / applied;
}

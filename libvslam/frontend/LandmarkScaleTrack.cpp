#include <libvslam/config/StrictRead.h>
#include <libvslam/frontend/LandmarkScaleTrack.h>
#include <libvslam/models/CMotionModel.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace vslam;

namespace
{
/** 99% quantile of chi-square with 2 degrees of freedom. */
constexpr double kGate99 = 9.21;
}  // namespace

CLandmarkScaleTrack::CLandmarkScaleTrack(double creationBaseline, const TScaleTrackOptions& settings)
	: m_settings(settings)
{
	if (!(creationBaseline > 0) || !(settings.odometrySigma > 0))
		throw std::invalid_argument("CLandmarkScaleTrack: baseline and odometry sigma must be positive");
	m_fixedInformation = creationBaseline / (settings.odometrySigma * settings.odometrySigma);
	m_fixedWeightedSum = m_fixedInformation;
	m_information = m_fixedInformation;
	m_weightedSum = m_fixedWeightedSum;
}

CLandmarkScaleTrack CLandmarkScaleTrack::resumed(const TState& state, const TScaleTrackOptions& settings)
{
	const bool positive = state.information > 0 && state.weightedSum > 0 && std::isfinite(state.information) &&
		std::isfinite(state.weightedSum);
	if (!positive) throw std::invalid_argument("CLandmarkScaleTrack: a resumed state must be positive and finite");
	CLandmarkScaleTrack track;
	track.m_settings = settings;
	track.m_fixedInformation = track.m_information = state.information;
	track.m_fixedWeightedSum = track.m_weightedSum = state.weightedSum;
	track.m_foldedUsed = track.m_used = state.pairsUsed;
	track.m_foldedRejected = track.m_rejected = state.pairsRejected;
	return track;
}

double CLandmarkScaleTrack::scaleErrorStd() const { return 1 / std::sqrt(m_information); }

double CLandmarkScaleTrack::addSighting(const ScaleSighting& s)
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

	Pair pair;
	pair.vv = visX * visX + visY * visY;
	pair.vo = visX * odoX + visY * odoY;
	pair.oo = odoX * odoX + odoY * odoY;
	pair.sightingsVariance = m_anchor->stdPosition * m_anchor->stdPosition + now.stdPosition * now.stdPosition;
	pair.travel = travel;
	m_anchor = now;
	if (!std::isfinite(pair.vv + pair.vo + pair.oo) || !(pair.variance(scaleError(), m_settings.odometrySigma) > 0))
	{
		m_foldedRejected++;  // measures nothing; never judged again
		m_rejected++;
		return 1;
	}
	if (m_pairs.size() == kJudgedPairs) foldOldestPair();
	m_pairs.push_back(pair);
	estimate();
	return appliedFactor() / applied;
}

void CLandmarkScaleTrack::foldOldestPair()
{
	const Pair& oldest = m_pairs.front();
	const double variance = oldest.variance(scaleError(), m_settings.odometrySigma);
	const double information = oldest.displacementSquared(m_settings.odometrySigma) / variance;
	if (oldest.used && m_fixedWeightedSum + oldest.vo / variance > 0 && m_fixedInformation + information > 0)
	{
		m_fixedInformation += information;
		m_fixedWeightedSum += oldest.vo / variance;
		m_foldedUsed++;
	}
	else
		m_foldedRejected++;
	m_pairs.erase(m_pairs.begin());
}

void CLandmarkScaleTrack::estimate()
{
	const double kBefore = scaleError();
	// Each pair's variance and its information on k, with k as it was.
	std::vector<double> variance(m_pairs.size()), pairInformation(m_pairs.size());
	for (size_t i = 0; i < m_pairs.size(); i++)
	{
		variance[i] = m_pairs[i].variance(kBefore, m_settings.odometrySigma);
		pairInformation[i] = m_pairs[i].displacementSquared(m_settings.odometrySigma) / variance[i];
		m_pairs[i].used = true;
	}
	for (;;)
	{
		double information = m_fixedInformation, weightedSum = m_fixedWeightedSum;
		for (size_t i = 0; i < m_pairs.size(); i++)
			if (m_pairs[i].used)
			{
				information += pairInformation[i];
				weightedSum += m_pairs[i].vo / variance[i];
			}
		// The worst pair against the estimate without it.
		double worst = -1;
		size_t worstAt = m_pairs.size();
		for (size_t i = 0; i < m_pairs.size(); i++)
		{
			if (!m_pairs[i].used) continue;
			const Pair& p = m_pairs[i];
			const double othersInformation = information - pairInformation[i];
			const double k = (weightedSum - p.vo / variance[i]) / othersInformation;
			const double residual = std::max(0.0, p.vv - 2 * k * p.vo + k * k * p.oo);
			const double chi2 = residual / (variance[i] + p.oo / othersInformation);
			if (chi2 > worst) worst = chi2, worstAt = i;
		}
		// A non-positive estimate (or information) is no scale: drop the worst pair too.
		if (worstAt < m_pairs.size() && (worst > kGate99 || !(weightedSum > 0) || !(information > 0)))
		{
			m_pairs[worstAt].used = false;
			continue;
		}
		m_information = information;
		m_weightedSum = weightedSum;
		break;
	}
	m_used = m_foldedUsed, m_rejected = m_foldedRejected;
	for (const Pair& p : m_pairs) (p.used ? m_used : m_rejected)++;
}

void CLandmarkScaleTrack::TOptions::takeOdometryNoiseFrom(double motionModelSigmaT)
{
	if (odometry_sigma == 0) odometry_sigma = motionModelSigmaT;
}

TScaleTrackOptions CLandmarkScaleTrack::TOptions::settings() const
{
	TScaleTrackOptions s;
	s.odometrySigma = odometry_sigma > 0 ? odometry_sigma : CMotionModel::TOptions().sigma_T;
	return s;
}

void CLandmarkScaleTrack::TOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace config;
	enabled = readBool(c, s, "enabled", enabled);
	odometry_sigma = readDouble(c, s, "odometry_sigma", odometry_sigma, Range::closed(0, 10));
}

void CLandmarkScaleTrack::TOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "enabled", enabled, 30, 10, "Refine landmark scales from later sightings and odometry");
	c.write(s, "odometry_sigma", odometry_sigma, 30, 10, "Odometry translation noise [m/sqrt(m)] (0: [vslam_motion_model] sigma_T)");
}

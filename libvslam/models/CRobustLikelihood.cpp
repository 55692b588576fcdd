#include <libvslam/config/StrictRead.h>
#include <libvslam/models/CRobustLikelihood.h>
#include <libvslam/models/ChiSquare.h>

#include <cmath>

using namespace vslam;
using namespace vslam::config;

void CRobustLikelihood::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	outlier_probability = readDouble(
		c, s, "outlier_probability", outlier_probability,
		Range::halfOpen(0, 1));
	outlier_max_range = readDouble(
		c, s, "outlier_max_range", outlier_max_range, Range::positive());
	gate_probability = readDouble(
		c, s, "gate_probability", gate_probability, {0, 1, false, false});
}

void CRobustLikelihood::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "outlier_probability", outlier_probability, 25, 12,
		"Weight of the uniform outlier component of the likelihood [0,1)");
	c.write(s, "outlier_max_range", outlier_max_range, 25, 12,
		"Extent of the measurement space for the outlier density [m]");
	c.write(s, "gate_probability", gate_probability, 25, 12,
		"Chi-square validation gate; outside it a particle's landmark KF "
		"skips the update");
}

void CRobustLikelihood::setOptions(const TOptions& o)
{
	m_options = o;
	const double eps = o.outlier_probability, r = o.outlier_max_range;
	m_logInlier = std::log1p(-eps);
	const double logEps = eps > 0 ? std::log(eps)
								  : -std::numeric_limits<double>::infinity();
	m_logOutlierPose = logEps - std::log(4 * r * r * 2 * M_PI);
	m_logOutlierPoint = logEps - std::log(r * 2 * M_PI);
	for (int d = 1; d <= 3; d++)
		m_gate[d] = chiSquareQuantile(o.gate_probability, d);
}

double CRobustLikelihood::logLikelihood(
	const MeasurementEvaluation& e, LandmarkKind kind) const
{
	const double logOut =
		kind == LandmarkKind::Pose ? m_logOutlierPose : m_logOutlierPoint;
	if (!e.gaussian.valid) return logOut;
	return logSumExp(m_logInlier + e.gaussian.logDensity, logOut);
}

bool CRobustLikelihood::inGate(const MeasurementEvaluation& e) const
{
	return e.gaussian.valid &&
		e.gaussian.mahalanobis2 <= m_gate[e.innovation.size()];
}

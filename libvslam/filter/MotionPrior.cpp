#include <libvslam/filter/MotionPrior.h>
#include <libvslam/models/Gaussian.h>
#include <mrpt/random/RandomGenerators.h>

#include <cmath>

using namespace vslam;

MotionPrior::Component::Component(const Eigen::Matrix3d& c) : cov(c)
{
	const Eigen::LLT<Eigen::Matrix3d> llt(cov);
	L = llt.matrixL();
	double logDet = 0;
	for (int i = 0; i < 3; i++) logDet += 2 * std::log(L(i, i));
	logNorm = -0.5 * (logDet + 3 * std::log(2 * M_PI));
}

double MotionPrior::Component::logDensity(const Eigen::Vector3d& e) const
{
	return logNorm - 0.5 * L.triangularView<Eigen::Lower>().solve(e).squaredNorm();
}

MotionPrior::MotionPrior(const COdometryAccumulator& acc, const CMotionModel& model)
	: m_u(acc.mean()),
	  m_narrow(acc.cov() + model.covarianceFloor()),
	  m_slip(acc.cov() + model.covarianceFloor() + model.slipCovariance()),
	  m_slipProbability(model.options.slip_probability),
	  m_moved(!acc.empty())
{
	m_logKeep = std::log1p(-m_slipProbability);
	m_logSlip = m_slipProbability > 0 ? std::log(m_slipProbability)
									  : -std::numeric_limits<double>::infinity();
}

se2::Pose MotionPrior::sample(mrpt::random::CRandomGenerator& rng, const se2::Pose& from) const
{
	const bool slip = m_slipProbability > 0 && rng.drawUniform(0.0, 1.0) < m_slipProbability;
	const Eigen::Vector3d n(
		rng.drawGaussian1D_normalized(), rng.drawGaussian1D_normalized(),
		rng.drawGaussian1D_normalized());
	const Eigen::Vector3d d = (slip ? m_slip.L : m_narrow.L) * n;
	return se2::compose(from, {m_u.x + d[0], m_u.y + d[1], m_u.phi + d[2]});
}

double MotionPrior::logDensity(const se2::Pose& from, const se2::Pose& s) const
{
	const Eigen::Vector3d e = se2::difference(se2::between(from, s), m_u);
	return logSumExp(m_logKeep + m_narrow.logDensity(e), m_logSlip + m_slip.logDensity(e));
}

Eigen::Matrix3d MotionPrior::toGlobal(const se2::Pose& from, const Eigen::Matrix3d& c) const
{
	const Eigen::Matrix3d J = se2::jacComposeB(from, m_u);
	return J * c * J.transpose();
}

Eigen::Matrix3d MotionPrior::globalCov(const se2::Pose& from) const
{
	return toGlobal(from, m_narrow.cov);
}

Eigen::Matrix3d MotionPrior::globalSlipCov(const se2::Pose& from) const
{
	return toGlobal(from, m_slip.cov);
}

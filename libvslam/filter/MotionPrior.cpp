#include <libvslam/filter/MotionPrior.h>
#include <mrpt/random/RandomGenerators.h>

#include <cmath>

using namespace vslam;

MotionPrior::MotionPrior(const COdometryAccumulator& acc, const CMotionModel& model)
	: m_u(acc.mean()), m_cov(acc.cov() + model.covarianceFloor()), m_moved(!acc.empty())
{
	const Eigen::LLT<Eigen::Matrix3d> llt(m_cov);
	m_L = llt.matrixL();
	double logDet = 0;
	for (int i = 0; i < 3; i++) logDet += 2 * std::log(m_L(i, i));
	m_logNorm = -0.5 * (logDet + 3 * std::log(2 * M_PI));
}

se2::Pose MotionPrior::sample(mrpt::random::CRandomGenerator& rng, const se2::Pose& from) const
{
	const Eigen::Vector3d n(
		rng.drawGaussian1D_normalized(), rng.drawGaussian1D_normalized(),
		rng.drawGaussian1D_normalized());
	const Eigen::Vector3d d = m_L * n;
	return se2::compose(from, {m_u.x + d[0], m_u.y + d[1], m_u.phi + d[2]});
}

double MotionPrior::logDensity(const se2::Pose& from, const se2::Pose& s) const
{
	const Eigen::Vector3d e = se2::difference(se2::between(from, s), m_u);
	return m_logNorm - 0.5 * m_L.triangularView<Eigen::Lower>().solve(e).squaredNorm();
}

Eigen::Matrix3d MotionPrior::globalCov(const se2::Pose& from) const
{
	const Eigen::Matrix3d J = se2::jacComposeB(from, m_u);
	return J * m_cov * J.transpose();
}

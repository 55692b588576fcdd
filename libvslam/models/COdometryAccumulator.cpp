#include <libvslam/models/COdometryAccumulator.h>

#include <cmath>

using namespace vslam;

void COdometryAccumulator::add(const se2::Pose& u, const Eigen::Matrix3d& cov)
{
	const Eigen::Matrix3d Ja = se2::jacComposeA(m_mean, u);
	const Eigen::Matrix3d Jb = se2::jacComposeB(m_mean, u);
	m_cov = Ja * m_cov * Ja.transpose() + Jb * cov * Jb.transpose();
	m_mean = se2::compose(m_mean, u);
	m_distance += std::hypot(u.x, u.y);
	m_rotation += std::abs(u.phi);
	m_count++;
	if (m_reference)
	{
		m_reference->cross = m_reference->cross * Ja.transpose();
		m_reference->atCurrent = false;
	}
}

void COdometryAccumulator::reset()
{
	std::optional<HeadingReference> reference;
	if (m_reference && m_reference->atCurrent)
		reference = HeadingReference{
			m_reference->time, {0, 0, 0}, Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero(), true};
	*this = COdometryAccumulator();
	m_reference = reference;
}

void COdometryAccumulator::setHeadingReference(mrpt::Clock::time_point t)
{
	m_reference = HeadingReference{t, m_mean, m_cov, m_cov, true};
}

COdometryAccumulator::HeadingFusion COdometryAccumulator::fuseHeadingChange(
	mrpt::Clock::time_point from, mrpt::Clock::time_point to, double dphi, double variance, double gateChi2)
{
	HeadingFusion result = HeadingFusion::NoReference;
	if (m_reference && m_reference->time == from)
	{
		const auto& r = *m_reference;
		// h = phi_now - phi_ref: its variance and its covariance with the
		// current pose (Cov(s, r) = cross^T).
		const double S = m_cov(2, 2) + r.cov(2, 2) - 2 * r.cross(2, 2) + variance;
		const Eigen::Vector3d covSh = m_cov.col(2) - r.cross.row(2).transpose();
		const double innovation = se2::wrap(dphi - se2::wrap(m_mean.phi - r.pose.phi));
		if (!(S > 0) || innovation * innovation / S > gateChi2)
			result = HeadingFusion::Gated;
		else
		{
			const Eigen::Vector3d K = covSh / S;
			m_mean = se2::fromVector(se2::toVector(m_mean) + K * innovation);
			m_cov -= K * S * K.transpose();
			m_cov = 0.5 * (m_cov + m_cov.transpose());
			result = HeadingFusion::Fused;
		}
	}
	setHeadingReference(to);
	return result;
}

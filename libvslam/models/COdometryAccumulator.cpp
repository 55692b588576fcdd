#include <libvslam/models/COdometryAccumulator.h>

#include <algorithm>
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
	for (auto& r : m_references)
	{
		r.cross = r.cross * Ja.transpose();
		r.atCurrent = false;
	}
}

void COdometryAccumulator::reset()
{
	std::vector<HeadingReference> kept;
	if (!m_references.empty() && m_references.back().atCurrent)
		kept.push_back(HeadingReference{
			m_references.back().time, {0, 0, 0}, Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero(), true});
	*this = COdometryAccumulator();
	m_references = std::move(kept);
}

void COdometryAccumulator::setHeadingReference(mrpt::Clock::time_point t)
{
	if (!m_references.empty() && m_references.back().time == t) m_references.pop_back();
	if (m_references.size() == kMaxReferences) m_references.erase(m_references.begin());
	m_references.push_back(HeadingReference{t, m_mean, m_cov, m_cov, true});
}

COdometryAccumulator::HeadingFusion COdometryAccumulator::fuseHeadingChange(
	mrpt::Clock::time_point from, mrpt::Clock::time_point to, double dphi, double variance, double gateChi2)
{
	HeadingFusion result = HeadingFusion::NoReference;
	const auto ref = std::find_if(m_references.rbegin(), m_references.rend(),
		[&](const HeadingReference& r) { return r.time == from; });
	if (ref != m_references.rend())
	{
		const auto& r = *ref;
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
	m_references.clear();
	setHeadingReference(to);
	return result;
}

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
}

void COdometryAccumulator::reset() { *this = COdometryAccumulator(); }

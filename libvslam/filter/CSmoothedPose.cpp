#include <libvslam/config/StrictRead.h>
#include <libvslam/filter/CSmoothedPose.h>

#include <algorithm>
#include <cmath>

namespace vslam
{
using namespace vslam::config;

void CSmoothedPose::TOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	time_constant = readDouble(c, s, "time_constant", time_constant, Range::closed(0, 3600));
	max_correction_speed = readDouble(c, s, "max_correction_speed", max_correction_speed, Range::positive());
}

void CSmoothedPose::TOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "time_constant", time_constant, 25, 12,
		"smoothed_path.tum: how fast it takes in the filter's corrections [s] (0: at once)");
	c.write(s, "max_correction_speed", max_correction_speed, 25, 12,
		"smoothed_path.tum: fastest correction [m/s] (heading: rad/s over a 1 m lever)");
}

const se2::Pose& CSmoothedPose::update(const se2::Pose& u, double dt, const se2::Pose& mean, bool jump)
{
	if (!m_pose || jump) return *(m_pose = mean);
	se2::Pose p = se2::compose(*m_pose, u);
	double ex = mean.x - p.x, ey = mean.y - p.y, ephi = se2::wrap(mean.phi - p.phi);
	const double share = m_o.time_constant > 0 ? 1 - std::exp(-std::max(0.0, dt) / m_o.time_constant) : 1.0;
	ex *= share, ey *= share, ephi *= share;
	// The fastest a correction may move it this step.
	const double cap = m_o.max_correction_speed * std::max(0.0, dt), norm = std::hypot(ex, ey);
	if (norm > cap) ex *= cap / norm, ey *= cap / norm;
	ephi = std::clamp(ephi, -cap, cap);
	p.x += ex, p.y += ey, p.phi = se2::wrap(p.phi + ephi);
	return *(m_pose = p);
}
}  // namespace vslam

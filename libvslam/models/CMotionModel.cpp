#include <libvslam/config/StrictRead.h>
#include <libvslam/models/CMotionModel.h>

#include <cmath>

using namespace vslam;
using namespace vslam::config;

void CMotionModel::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	sigma_T = readDouble(c, s, "sigma_T", sigma_T, Range::closed(0, 10));
	sigma_R = readDouble(c, s, "sigma_R", sigma_R, Range::closed(0, 10));
	sigma_R_per_meter = readDouble(
		c, s, "sigma_R_per_meter", sigma_R_per_meter, Range::closed(0, 10));
	slip_probability =
		readDouble(c, s, "slip_probability", slip_probability, Range::halfOpen(0, 1));
	slip_std_xy = readDouble(c, s, "slip_std_xy", slip_std_xy, Range{0, 100, false, true});
	slip_std_phi =
		readDegreesAsRadians(c, s, "slip_std_phi_deg", slip_std_phi, Range{0, 360, false, true});
}

void CMotionModel::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "sigma_T", sigma_T, 25, 12,
		"Translational odometry noise [m/sqrt(m)]: var(x)=var(y)=sigma_T^2*d");
	c.write(s, "sigma_R", sigma_R, 25, 12,
		"Rotational odometry noise [rad/sqrt(rad)]: var(th)+=sigma_R^2*|dth|");
	c.write(s, "sigma_R_per_meter", sigma_R_per_meter, 25, 12,
		"Heading drift per distance [rad/sqrt(m)]: var(th)+=s^2*d (0: paper)");
	c.write(s, "slip_probability", slip_probability, 25, 12,
		"Probability that one update's odometry failed (slip, bump), [0,1)");
	c.write(s, "slip_std_xy", slip_std_xy, 25, 12, "Position error of such a failure [m]");
	c.write(s, "slip_std_phi_deg", slip_std_phi * 180.0 / M_PI, 25, 12,
		"Heading error of such a failure [deg]");
}

Eigen::Matrix3d CMotionModel::incrementCovariance(const se2::Pose& u) const
{
	const double d = std::hypot(u.x, u.y);
	const double varXY = options.sigma_T * options.sigma_T * d;
	const double varPhi = options.sigma_R * options.sigma_R * std::abs(u.phi) +
		options.sigma_R_per_meter * options.sigma_R_per_meter * d;
	return Eigen::Vector3d(varXY, varXY, varPhi).asDiagonal();
}

Eigen::Matrix3d CMotionModel::slipCovariance() const
{
	const double a = options.slip_std_xy * options.slip_std_xy;
	const double b = options.slip_std_phi * options.slip_std_phi;
	return Eigen::Vector3d(a, a, b).asDiagonal();
}

Eigen::Matrix3d CMotionModel::covarianceFloor() const
{
	constexpr double kMinStdXY = 1e-4, kMinStdPhi = 1e-4;  // m, rad
	const double a = kMinStdXY * kMinStdXY;
	const double b = kMinStdPhi * kMinStdPhi;
	return Eigen::Vector3d(a, a, b).asDiagonal();
}

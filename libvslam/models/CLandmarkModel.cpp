#include <libvslam/models/CLandmarkModel.h>

#include <cmath>

namespace vslam
{
namespace
{
se2::Pose asPose(const LandmarkEstimate& l)
{
	return {l.mean[0], l.mean[1], l.mean[2]};
}

/** Range and bearing geometry from the sensor at s (+) sensorPose. */
struct RangeBearingGeometry
{
	se2::Pose sensor;
	double dx = 0, dy = 0, r2 = 0, r = 0;
};

RangeBearingGeometry geometry(
	const se2::Pose& s, const se2::Pose& sensorPose, const Eigen::Vector3d& l)
{
	RangeBearingGeometry g;
	g.sensor = se2::compose(s, sensorPose);
	g.dx = l[0] - g.sensor.x;
	g.dy = l[1] - g.sensor.y;
	// A landmark exactly at the sensor has no bearing: keep r away from 0.
	g.r2 = std::max(g.dx * g.dx + g.dy * g.dy, 1e-12);
	g.r = std::sqrt(g.r2);
	return g;
}
}  // namespace

LandmarkEstimate CLandmarkModel::initialize(
	const se2::Pose& s, const LandmarkMeasurement& m, const Eigen::Matrix3d* robotPoseCov) const
{
	LandmarkEstimate l = initializeFromMeasurement(s, m);
	if (robotPoseCov)
	{
		// Padded to 3x3 (zero rows for point landmarks), so the unused block
		// of the fixed-size covariance stays zero.
		Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
		J.topRows(l.dim()) = inverseJacobianRobot(s, m);
		l.cov += J * (*robotPoseCov) * J.transpose();
	}
	return l;
}

// --------------------------------------------------------------------------
// Pose landmarks
// --------------------------------------------------------------------------
MeasurementPrediction CPoseLandmarkModel::predict(
	const se2::Pose& s, const LandmarkEstimate& l,
	const LandmarkMeasurement& /*m*/) const
{
	// between(s, l) and its Jacobians, sharing one sin/cos.
	const double c = std::cos(s.phi), sn = std::sin(s.phi);
	const double dx = l.mean[0] - s.x, dy = l.mean[1] - s.y;
	const double zx = c * dx + sn * dy, zy = -sn * dx + c * dy;
	MeasurementPrediction p;
	p.zhat.resize(3);
	p.zhat << zx, zy, se2::wrap(l.mean[2] - s.phi);
	p.H_robot = MatN(3, 3);
	p.H_robot << -c, -sn, zy,  //
		sn, -c, -zx,  //
		0, 0, -1;
	p.H_landmark = MatN(3, 3);
	p.H_landmark << c, sn, 0,  //
		-sn, c, 0,  //
		0, 0, 1;
	return p;
}

VecN CPoseLandmarkModel::innovation(
	const LandmarkMeasurement& m, const VecN& zhat) const
{
	VecN nu = m.z - zhat;
	nu[2] = se2::wrap(nu[2]);
	return nu;
}

MatN CPoseLandmarkModel::inverseJacobianRobot(
	const se2::Pose& s, const LandmarkMeasurement& m) const
{
	return se2::jacComposeA(s, {m.z[0], m.z[1], m.z[2]});
}

LandmarkEstimate CPoseLandmarkModel::initializeFromMeasurement(
	const se2::Pose& s, const LandmarkMeasurement& m) const
{
	const se2::Pose z{m.z[0], m.z[1], m.z[2]};
	const Eigen::Matrix3d J = se2::jacComposeB(s, z);
	LandmarkEstimate l;
	l.kind = LandmarkKind::Pose;
	l.mean = se2::toVector(se2::compose(s, z));
	l.cov = J * Eigen::Matrix3d(m.R) * J.transpose();
	return l;
}

CDualProposal CPoseLandmarkModel::dualProposal(
	const LandmarkEstimate& l, const LandmarkMeasurement& m,
	const HeadingPrior& /*fully determined by the measurement*/) const
{
	const se2::Pose lp = asPose(l);
	const se2::Pose z{m.z[0], m.z[1], m.z[2]};
	const se2::Pose zInv = se2::inverse(z);
	const Eigen::Matrix3d Jl = se2::jacComposeA(lp, zInv);
	const Eigen::Matrix3d Jz = se2::jacComposeB(lp, zInv) * se2::jacInverse(z);
	const Eigen::Matrix3d C = Jl * l.cov * Jl.transpose() +
		Jz * Eigen::Matrix3d(m.R) * Jz.transpose();
	return CDualProposal(makePoseGaussianProposal(se2::compose(lp, zInv), C));
}

// --------------------------------------------------------------------------
// Point landmarks (range-bearing)
// --------------------------------------------------------------------------
MeasurementPrediction CPointLandmarkModel::predict(
	const se2::Pose& s, const LandmarkEstimate& l,
	const LandmarkMeasurement& m) const
{
	const RangeBearingGeometry g = geometry(s, m.sensorPose, l.mean);
	MeasurementPrediction p;
	p.zhat.resize(2);
	p.zhat << g.r, se2::wrap(std::atan2(g.dy, g.dx) - g.sensor.phi);

	// d h / d sensorPose, then chain through sensor = s (+) sensorPose.
	Eigen::Matrix<double, 2, 3> H_sensor;
	H_sensor << -g.dx / g.r, -g.dy / g.r, 0,  //
		g.dy / g.r2, -g.dx / g.r2, -1;
	p.H_robot = H_sensor * se2::jacComposeA(s, m.sensorPose);

	p.H_landmark = MatN(2, 2);
	p.H_landmark << g.dx / g.r, g.dy / g.r,  //
		-g.dy / g.r2, g.dx / g.r2;
	return p;
}

VecN CPointLandmarkModel::innovation(
	const LandmarkMeasurement& m, const VecN& zhat) const
{
	VecN nu = m.z - zhat;
	nu[1] = se2::wrap(nu[1]);
	return nu;
}

MatN CPointLandmarkModel::inverseJacobianRobot(
	const se2::Pose& s, const LandmarkMeasurement& m) const
{
	// l = sensor.xy + r (cos a, sin a), a = sensor.phi + b, sensor = s (+) t.
	const se2::Pose sensor = se2::compose(s, m.sensorPose);
	const double a = sensor.phi + m.z[1];
	Eigen::Matrix<double, 2, 3> dl_dsensor;
	dl_dsensor << 1, 0, -m.z[0] * std::sin(a),  //
		0, 1, m.z[0] * std::cos(a);
	return dl_dsensor * se2::jacComposeA(s, m.sensorPose);
}

LandmarkEstimate CPointLandmarkModel::initializeFromMeasurement(
	const se2::Pose& s, const LandmarkMeasurement& m) const
{
	const se2::Pose sensor = se2::compose(s, m.sensorPose);
	const double r = m.z[0], a = sensor.phi + m.z[1];
	const double c = std::cos(a), sn = std::sin(a);
	Eigen::Matrix2d G;
	G << c, -r * sn,  //
		sn, r * c;
	LandmarkEstimate l;
	l.kind = LandmarkKind::Point;
	l.mean << sensor.x + r * c, sensor.y + r * sn, 0;
	l.cov.setZero();
	l.cov.topLeftCorner<2, 2>() = G * Eigen::Matrix2d(m.R) * G.transpose();
	return l;
}

CDualProposal CPointLandmarkModel::dualProposal(
	const LandmarkEstimate& l, const LandmarkMeasurement& m,
	const HeadingPrior& headingPrior) const
{
	PointRangeBearingProposal p;
	p.heading = headingPrior;
	p.landmark = l.mean.head<2>();
	p.landmarkCov = l.cov.topLeftCorner<2, 2>();
	p.range = m.z[0];
	p.bearing = m.z[1];
	p.rangeBearingCov = Eigen::Matrix2d(m.R);
	p.sensorPose = m.sensorPose;
	return CDualProposal(p);
}

const CLandmarkModel& landmarkModel(LandmarkKind kind)
{
	static const CPoseLandmarkModel pose;
	static const CPointLandmarkModel point;
	if (kind == LandmarkKind::Pose) return pose;
	return point;
}

}  // namespace vslam

#include <libvslam/models/MeasurementUpdate.h>

#include <Eigen/LU>

namespace vslam
{
namespace
{
/** True if the symmetric D x D matrix S is positive definite (leading
 * minors), with its closed-form inverse and determinant. */
template <int D>
bool invertSpd(
	const Eigen::Matrix<double, D, D>& S, Eigen::Matrix<double, D, D>& inv, double& det)
{
	det = S.determinant();
	if (!(S(0, 0) > 0) || !(det > 0)) return false;
	if constexpr (D == 3)
		if (!(S(0, 0) * S(1, 1) - S(0, 1) * S(1, 0) > 0)) return false;
	inv = S.inverse();
	return true;
}

/** The hot arithmetic on fixed-size matrices (2 or 3), with closed-form
 * inverses: dynamic-size or LLT-based small-matrix code is several times
 * slower. */
template <int D>
void finishEvaluation(
	const MatN& H_robot, const LandmarkEstimate& l, const Eigen::Matrix3d* robotPoseCov,
	MeasurementEvaluation& e, const MatN& R)
{
	using MatD = Eigen::Matrix<double, D, D>;
	using VecD = Eigen::Matrix<double, D, 1>;
	const MatD Hl = e.H_landmark.template topLeftCorner<D, D>();
	MatD S = R.template topLeftCorner<D, D>() +
		Hl * l.cov.template topLeftCorner<D, D>() * Hl.transpose();
	if (robotPoseCov)
	{
		const Eigen::Matrix<double, D, 3> Hs = H_robot.template topLeftCorner<D, 3>();
		S += Hs * (*robotPoseCov) * Hs.transpose();
	}
	e.S = S;
	MatD Sinv;
	double det = 0;
	if (!invertSpd<D>(S, Sinv, det)) return;
	e.Sinv = Sinv;
	const VecD nu = e.innovation.template head<D>();
	e.gaussian.mahalanobis2 = nu.dot(Sinv * nu);
	e.gaussian.logDensity =
		-0.5 * (e.gaussian.mahalanobis2 + std::log(det) + D * std::log(2.0 * M_PI));
	e.gaussian.valid = true;
}

template <int D>
void fixedKalmanUpdate(LandmarkEstimate& l, const MeasurementEvaluation& e)
{
	using MatD = Eigen::Matrix<double, D, D>;
	const MatD P = l.cov.template topLeftCorner<D, D>();
	const MatD H = e.H_landmark.template topLeftCorner<D, D>();
	const MatD S = e.S.template topLeftCorner<D, D>();
	const MatD K = P * H.transpose() * e.Sinv.template topLeftCorner<D, D>();
	l.mean.template head<D>() += K * e.innovation.template head<D>();
	const MatD Pn = P - K * S * K.transpose();
	l.cov.template topLeftCorner<D, D>() = 0.5 * (Pn + Pn.transpose());
}
}  // namespace

MeasurementEvaluation evaluateMeasurement(
	const CLandmarkModel& model, const se2::Pose& s, const LandmarkEstimate& l,
	const LandmarkMeasurement& m, const Eigen::Matrix3d* robotPoseCov)
{
	const MeasurementPrediction p = model.predict(s, l, m);
	MeasurementEvaluation e;
	e.innovation = model.innovation(m, p.zhat);
	e.H_landmark = p.H_landmark;
	if (m.dim() == 3)
		finishEvaluation<3>(p.H_robot, l, robotPoseCov, e, m.R);
	else
		finishEvaluation<2>(p.H_robot, l, robotPoseCov, e, m.R);
	return e;
}

void kalmanUpdate(LandmarkEstimate& l, const MeasurementEvaluation& e)
{
	if (!e.gaussian.valid) return;
	if (l.dim() == 3)
		fixedKalmanUpdate<3>(l, e);
	else
		fixedKalmanUpdate<2>(l, e);
	if (l.kind == LandmarkKind::Pose) l.mean[2] = se2::wrap(l.mean[2]);
	l.updates++;
}

}  // namespace vslam

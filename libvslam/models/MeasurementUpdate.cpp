#include <libvslam/models/MeasurementUpdate.h>

namespace vslam
{
MeasurementEvaluation evaluateMeasurement(
	const CLandmarkModel& model, const se2::Pose& s, const LandmarkEstimate& l,
	const LandmarkMeasurement& m, const Eigen::Matrix3d* robotPoseCov)
{
	const MeasurementPrediction p = model.predict(s, l, m);
	MeasurementEvaluation e;
	e.innovation = model.innovation(m, p.zhat);
	e.H_landmark = p.H_landmark;
	e.S = m.R + p.H_landmark * l.covN() * p.H_landmark.transpose();
	if (robotPoseCov)
		e.S += p.H_robot * (*robotPoseCov) * p.H_robot.transpose();
	e.gaussian = evaluateGaussian(e.innovation, e.S);
	return e;
}

void kalmanUpdate(LandmarkEstimate& l, const MeasurementEvaluation& e)
{
	const int d = l.dim();
	const MatN P = l.covN();
	const Eigen::LLT<MatN> llt(e.S);
	if (llt.info() != Eigen::Success) return;
	// K = P H^T S^-1, computed as (S^-1 H P)^T (S and P symmetric).
	const MatN K = llt.solve(e.H_landmark * P).transpose();
	l.mean.head(d) += K * e.innovation;
	MatN Pn = P - K * e.S * K.transpose();
	Pn = 0.5 * (Pn + Pn.transpose());
	l.cov.topLeftCorner(d, d) = Pn;
	if (l.kind == LandmarkKind::Pose) l.mean[2] = se2::wrap(l.mean[2]);
	l.updates++;
}

}  // namespace vslam

#include <libvslam/filter/OptimalProposal.h>
#include <libvslam/models/CLandmarkModel.h>

#include <Eigen/LU>

namespace vslam
{
namespace
{
/** One EKF step of the pose (mean, C) with a measurement of dimension D;
 * false if the measurement is outside its validation gate. */
template <int D>
bool poseUpdate(
	const CLandmarkModel& model, const LandmarkEstimate& l, const LandmarkMeasurement& m,
	const CRobustLikelihood& likelihood, se2::Pose& mean, Eigen::Matrix3d& C)
{
	using MatD = Eigen::Matrix<double, D, D>;
	using VecD = Eigen::Matrix<double, D, 1>;
	const MeasurementPrediction p = model.predict(mean, l, m);
	const VecD nu = model.innovation(m, p.zhat).template head<D>();
	const Eigen::Matrix<double, D, 3> Hs = p.H_robot.template topLeftCorner<D, 3>();
	const MatD Hl = p.H_landmark.template topLeftCorner<D, D>();
	const MatD S = m.R.template topLeftCorner<D, D>() +
		Hl * l.cov.template topLeftCorner<D, D>() * Hl.transpose() + Hs * C * Hs.transpose();
	const double det = S.determinant();
	if (!(S(0, 0) > 0) || !(det > 0)) return false;
	const MatD Sinv = S.inverse();
	if (nu.dot(Sinv * nu) > likelihood.gate(D)) return false;
	const Eigen::Matrix<double, 3, D> K = C * Hs.transpose() * Sinv;
	const Eigen::Vector3d dx = K * nu;
	mean = {mean.x + dx[0], mean.y + dx[1], se2::wrap(mean.phi + dx[2])};
	C -= K * S * K.transpose();
	C = 0.5 * (C + C.transpose());
	return true;
}
}  // namespace

PoseGaussianProposal optimalProposal(
	const se2::Pose& predicted, const Eigen::Matrix3d& predictedCov, const LandmarkBank& bank,
	const std::vector<KnownMeasurement>& measurements, const CRobustLikelihood& likelihood,
	std::vector<char>* inGate)
{
	se2::Pose mean = predicted;
	Eigen::Matrix3d C = predictedCov;
	if (inGate) inGate->assign(measurements.size(), 0);
	for (size_t i = 0; i < measurements.size(); i++)
	{
		const auto& k = measurements[i];
		const auto& model = landmarkModel(k.m->kind());
		const bool used = k.m->dim() == 3
			? poseUpdate<3>(model, bank[k.slot], *k.m, likelihood, mean, C)
			: poseUpdate<2>(model, bank[k.slot], *k.m, likelihood, mean, C);
		if (inGate) (*inGate)[i] = used;
	}
	return makePoseGaussianProposal(mean, C);
}
}  // namespace vslam

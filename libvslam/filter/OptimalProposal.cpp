#include <libvslam/filter/OptimalProposal.h>
#include <libvslam/models/CLandmarkModel.h>

namespace vslam
{
PoseGaussianProposal optimalProposal(
	const se2::Pose& previous, const MotionPrior& motion, const LandmarkBank& bank,
	const std::vector<KnownMeasurement>& measurements, const CRobustLikelihood& likelihood)
{
	se2::Pose mean = se2::compose(previous, motion.increment());
	Eigen::Matrix3d C = motion.globalCov(previous);
	for (const auto& k : measurements)
	{
		const auto& model = landmarkModel(k.m->kind());
		const LandmarkEstimate& l = bank[k.slot];
		const MeasurementPrediction p = model.predict(mean, l, *k.m);
		const VecN nu = model.innovation(*k.m, p.zhat);
		const MatN Hs = p.H_robot;
		const MatN S = k.m->R + p.H_landmark * l.covN() * p.H_landmark.transpose() +
			Hs * C * Hs.transpose();
		const Eigen::LLT<MatN> llt(S);
		if (llt.info() != Eigen::Success) continue;
		const VecN y = llt.matrixL().solve(nu);
		if (y.squaredNorm() > likelihood.gate(static_cast<int>(nu.size()))) continue;
		// K = C Hs^T S^-1, computed as (S^-1 Hs C)^T.
		const Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 3> K =
			llt.solve(Hs * C).transpose();
		const Eigen::Vector3d dx = K * nu;
		mean = {mean.x + dx[0], mean.y + dx[1], se2::wrap(mean.phi + dx[2])};
		C = C - K * S * K.transpose();
		C = 0.5 * (C + C.transpose());
	}
	return makePoseGaussianProposal(mean, C);
}
}  // namespace vslam

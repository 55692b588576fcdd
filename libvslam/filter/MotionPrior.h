#pragma once
/** \file MotionPrior.h
 * The odometry accumulated since the last update, ready for sampling
 * (nominal particles) and for evaluating the motion density (mixture
 * weights): s = from (+) (u + w), w in the frame of `from`, with w drawn
 * from (1 - eps) N(0, C) + eps N(0, C + C_slip) (CMotionModel.h). */
#include <libvslam/models/CMotionModel.h>
#include <libvslam/models/COdometryAccumulator.h>
#include <libvslam/models/SE2.h>

#include <Eigen/Cholesky>

namespace mrpt::random
{
class CRandomGenerator;
}

namespace vslam
{
class MotionPrior
{
   public:
	/** The accumulated increment with the model's covariance floor added. */
	MotionPrior(const COdometryAccumulator& acc, const CMotionModel& model);

	const se2::Pose& increment() const { return m_u; }
	/** Covariance of the regular component, in the increment's start frame
	 * (floor included). */
	const Eigen::Matrix3d& cov() const { return m_narrow.cov; }
	bool moved() const { return m_moved; }

	/** Draws s ~ p(s | from, u). */
	se2::Pose sample(mrpt::random::CRandomGenerator& rng, const se2::Pose& from) const;
	/** log p(s | from, u). */
	double logDensity(const se2::Pose& from, const se2::Pose& s) const;
	/** Covariance of the predicted pose from `from`, in the global frame
	 * (regular component). */
	Eigen::Matrix3d globalCov(const se2::Pose& from) const;
	/** The same for the slip component. */
	Eigen::Matrix3d globalSlipCov(const se2::Pose& from) const;

   private:
	struct Component
	{
		Eigen::Matrix3d cov, L;
		double logNorm = 0;
		explicit Component(const Eigen::Matrix3d& c);
		double logDensity(const Eigen::Vector3d& e) const;
	};
	se2::Pose m_u{0, 0, 0};
	Component m_narrow, m_slip;
	double m_logKeep = 0, m_logSlip = 0, m_slipProbability = 0;
	bool m_moved = false;

	Eigen::Matrix3d toGlobal(const se2::Pose& from, const Eigen::Matrix3d& c) const;
};
}  // namespace vslam

#pragma once
/** \file MotionPrior.h
 * The odometry accumulated since the last update, ready for sampling
 * (nominal particles) and for evaluating the motion density (mixture
 * weights): s = from (+) (u + w), w ~ N(0, cov) in the frame of `from`. */
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
	/** Covariance in the increment's start frame (floor included). */
	const Eigen::Matrix3d& cov() const { return m_cov; }
	bool moved() const { return m_moved; }

	/** Draws s ~ p(s | from, u). */
	se2::Pose sample(mrpt::random::CRandomGenerator& rng, const se2::Pose& from) const;
	/** log p(s | from, u). */
	double logDensity(const se2::Pose& from, const se2::Pose& s) const;
	/** Covariance of the predicted pose from `from`, in the global frame. */
	Eigen::Matrix3d globalCov(const se2::Pose& from) const;

   private:
	se2::Pose m_u{0, 0, 0};
	Eigen::Matrix3d m_cov, m_L;
	double m_logNorm = 0;
	bool m_moved = false;
};
}  // namespace vslam

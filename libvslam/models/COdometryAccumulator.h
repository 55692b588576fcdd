#pragma once
/** \file COdometryAccumulator.h
 * Composes odometry increments between two filter updates into one Gaussian
 * increment (first-order covariance propagation), so the particles are
 * sampled once per accumulated increment, as MRPT's RBPF does: many small
 * increments do not make the cloud diffuse artificially, and a path that
 * goes out and back keeps the uncertainty of the whole trip.
 */
#include <libvslam/models/SE2.h>

#include <Eigen/Core>

namespace vslam
{
class COdometryAccumulator
{
   public:
	/** Appends increment u (in the frame where it starts) with covariance
	 * cov (in that same frame). */
	void add(const se2::Pose& u, const Eigen::Matrix3d& cov);
	void reset();

	/** The composed increment since the last reset. */
	const se2::Pose& mean() const { return m_mean; }
	/** Its covariance, in the frame of the pose where it starts. */
	const Eigen::Matrix3d& cov() const { return m_cov; }
	/** Path length travelled since the last reset (m). */
	double distance() const { return m_distance; }
	/** Absolute rotation since the last reset (rad). */
	double rotation() const { return m_rotation; }
	/** True if no increment was added since the last reset. */
	bool empty() const { return m_count == 0; }

   private:
	se2::Pose m_mean{0, 0, 0};
	Eigen::Matrix3d m_cov = Eigen::Matrix3d::Zero();
	double m_distance = 0, m_rotation = 0;
	size_t m_count = 0;
};
}  // namespace vslam

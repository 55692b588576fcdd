#pragma once
/** \file COdometryAccumulator.h
 * Composes odometry increments between two filter updates into one Gaussian
 * increment (first-order covariance propagation), so the particles are
 * sampled once per accumulated increment, as MRPT's RBPF does: many small
 * increments do not make the cloud diffuse artificially, and a path that
 * goes out and back keeps the uncertainty of the whole trip.
 *
 * A heading change measured between two moments (the front-end's visual
 * heading change between two images, CObservationHeadingChange) is fused
 * into the accumulated increment: the accumulator keeps the pose at the
 * last heading reference with its covariance and its cross-covariance with
 * the current pose, so a heading change from the reference to now is a
 * Kalman update of their joint Gaussian, h = phi_now - phi_reference. The
 * corrected increment (and its smaller covariance) is then what the
 * particles are drawn from. A reference is set where a heading change ends
 * (the next one starts there) and, by the caller, at every odometry reading
 * (an image that brought no heading change, such as the first one, can then
 * still start one); the last kMaxReferences are kept. The newest reference
 * survives reset() when it was set after the last increment (the filter
 * updates at the image that becomes the next reference); the others are
 * dropped there: part of their interval is already in the particles, and a
 * heading change from them cannot be fused.
 */
#include <libvslam/models/SE2.h>
#include <mrpt/core/Clock.h>

#include <Eigen/Core>
#include <vector>

namespace vslam
{
class COdometryAccumulator
{
   public:
	/** Appends increment u (in the frame where it starts) with covariance
	 * cov (in that same frame). */
	void add(const se2::Pose& u, const Eigen::Matrix3d& cov);
	/** Starts a new increment; keeps the heading reference set since the
	 * last add(), if any (now at the new start, with no uncertainty). */
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

	enum class HeadingFusion
	{
		Fused,
		NoReference,  //!< no reference at `from` (first image, a gap, a reset in between)
		Gated  //!< inconsistent with the odometry beyond the gate: not used
	};
	/** Marks the current pose, at time t, as where a later heading change
	 * may start (replacing a reference at the same time). */
	void setHeadingReference(mrpt::Clock::time_point t);
	/** Fuses the heading change dphi (rad, with `variance`) measured from
	 * the reference at `from` to now, unless its normalized innovation
	 * squared exceeds gateChi2 (1 degree of freedom); then the current pose
	 * becomes the only reference, at `to`, whatever the outcome (heading
	 * changes come in time order: none will start before `to`). */
	HeadingFusion fuseHeadingChange(mrpt::Clock::time_point from, mrpt::Clock::time_point to, double dphi,
		double variance, double gateChi2);

   private:
	se2::Pose m_mean{0, 0, 0};
	Eigen::Matrix3d m_cov = Eigen::Matrix3d::Zero();
	double m_distance = 0, m_rotation = 0;
	size_t m_count = 0;

	struct HeadingReference
	{
		mrpt::Clock::time_point time;
		se2::Pose pose;
		Eigen::Matrix3d cov;  //!< of the reference pose
		Eigen::Matrix3d cross;  //!< Cov(reference, current)
		bool atCurrent = true;  //!< nothing added since it was set
	};
	/** Oldest first; between two heading changes there are a few odometry
	 * readings, so a short window covers a gap of several images. */
	static constexpr size_t kMaxReferences = 16;
	std::vector<HeadingReference> m_references;
};
}  // namespace vslam

#pragma once
/** \file DualProposal.h
 * A "dual" sampling distribution q(s | z, l) over robot poses s that explain
 * one landmark measurement z given the particle's estimate of landmark l:
 * the measurement model inverted (doc/mixture-proposal.md). Both kinds can
 * draw a sample and evaluate their exact density at any pose, which the
 * mixture weights need for every particle.
 *
 *  - Pose landmark: s = l (+) z^-1, linearized into a Gaussian over
 *    (x, y, phi) with covariance J_l P J_l^T + J_z R J_z^T.
 *  - Point landmark: one range-bearing pins the position only up to the
 *    heading. The heading comes from a prior (the particle's predicted
 *    heading, or uniform on (-pi, pi] in kidnap mode); given the heading,
 *    the position is Gaussian around l - r (cos a, sin a) - R(phi) t_sensor.
 */
#include <libvslam/models/SE2.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <variant>

namespace mrpt::random
{
class CRandomGenerator;
}

namespace vslam
{
/** Prior on the heading of dual samples that a measurement leaves free. */
struct HeadingPrior
{
	bool uniform = false;
	double mean = 0;  //!< rad
	double std = 0;  //!< rad (> 0 unless uniform)

	static HeadingPrior Uniform() { return {true, 0, 0}; }
	static HeadingPrior Gaussian(double m, double s) { return {false, m, s}; }
};

/** Gaussian over (x, y, phi) with a wrapped angular difference. */
struct PoseGaussianProposal
{
	se2::Pose mean;
	Eigen::Matrix3d cov;
	Eigen::Matrix3d L;  //!< Cholesky factor of cov
	double logNorm = 0;  //!< -0.5 log|2 pi cov|
	bool valid = false;
};

/** Heading prior x Gaussian position given the heading. */
struct PointRangeBearingProposal
{
	HeadingPrior heading;
	Eigen::Vector2d landmark;
	Eigen::Matrix2d landmarkCov;
	double range = 0, bearing = 0;
	Eigen::Matrix2d rangeBearingCov;
	se2::Pose sensorPose;

	/** Mean and covariance of the robot position for a given heading. */
	void positionGivenHeading(
		double phi, Eigen::Vector2d& mean, Eigen::Matrix2d& cov) const;
};

class CDualProposal
{
   public:
	CDualProposal() = default;
	explicit CDualProposal(const PoseGaussianProposal& p) : m_p(p) {}
	explicit CDualProposal(const PointRangeBearingProposal& p) : m_p(p) {}

	/** False if the proposal is degenerate (e.g. singular covariance). */
	bool valid() const;
	se2::Pose sample(mrpt::random::CRandomGenerator& rng) const;
	double logDensity(const se2::Pose& s) const;
	/** Approximate covariance of the sampled positions (x, y), used to
	 * judge whether duals can sharpen the particle cloud. */
	Eigen::Matrix2d positionSpread() const;

   private:
	std::variant<std::monostate, PoseGaussianProposal, PointRangeBearingProposal>
		m_p;
};

/** Builds a PoseGaussianProposal from a mean and covariance. */
PoseGaussianProposal makePoseGaussianProposal(
	const se2::Pose& mean, const Eigen::Matrix3d& cov);

}  // namespace vslam

#pragma once
/** \file OdometryErrorModel.h
 * What wheel odometry reports for a true motion: the paper's two noise
 * parameters (sigma_T, sigma_R) plus heading drift per metre, systematic
 * scale and wheelbase (turn) biases, and rare wheel slips that move the
 * robot without odometry seeing it. Shared by both simulators.
 */
#include <libvslam/models/SE2.h>
#include <mrpt/random/RandomGenerators.h>

namespace vslam
{
struct TOdometryErrorModel
{
	double sigma_T = 0.05;  //!< m/sqrt(m)
	double sigma_R = 0.05;  //!< rad/sqrt(rad)
	double sigma_R_per_meter = 0.02;  //!< rad/sqrt(m)
	double scale_bias = 0.0;  //!< relative error of distances
	double turn_bias = 0.0;  //!< relative error of rotations
	double slip_probability = 0.0;  //!< per step
	double slip_std = 0.05;  //!< m, xy error of one slip

	/** The increment odometry reports for the true increment u = (forward,
	 * 0, turn) (draws three Gaussians). */
	se2::Pose measured(const se2::Pose& u, mrpt::random::CRandomGenerator& rng) const
	{
		const double d = std::abs(u.x), a = std::abs(u.phi);
		const double sT = sigma_T * std::sqrt(d);
		const double sR = std::sqrt(sigma_R * sigma_R * a + sigma_R_per_meter * sigma_R_per_meter * d);
		return {u.x * (1 + scale_bias) + sT * rng.drawGaussian1D_normalized(),
				sT * rng.drawGaussian1D_normalized(),
				u.phi * (1 + turn_bias) + sR * rng.drawGaussian1D_normalized()};
	}

	/** A slip to compose onto the true pose this step, if one happens
	 * (draws a uniform, and two Gaussians on a slip). */
	bool slip(mrpt::random::CRandomGenerator& rng, se2::Pose& slipIncrement) const
	{
		if (slip_probability <= 0 || rng.drawUniform(0, 1) >= slip_probability) return false;
		slipIncrement = {slip_std * rng.drawGaussian1D_normalized(), slip_std * rng.drawGaussian1D_normalized(), 0};
		return true;
	}
};
}  // namespace vslam

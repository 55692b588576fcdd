#pragma once
/** \file CMotionModel.h
 * The paper's odometry motion model s_{t+1} = f(s_t, u_t) + w_t with
 * E(w w^T) = g(theta_t, u_t, sigma_T, sigma_R). The paper leaves g open; ours
 * (doc/architecture.md): an odometry increment u = (dx, dy,
 * dtheta), expressed in the frame of the pose where it starts, is corrupted
 * by zero-mean Gaussian noise with covariance, in that same frame,
 *
 *     var(x) = var(y) = sigma_T^2 * d
 *     var(theta)      = sigma_R^2 * |dtheta| + sigma_R_per_meter^2 * d
 *
 * with d = |(dx, dy)|: a random walk in both translation and rotation
 * (holonomic drive: translation noise isotropic). Variances grow linearly
 * with the motion, so splitting one increment into many gives the same
 * total noise.
 *
 * Real odometry also fails now and then (wheel slip, a bump, a collision).
 * With probability slip_probability per update, the increment's error has
 * the extra covariance diag(slip_std_xy^2, slip_std_xy^2, slip_std_phi^2):
 * the motion prior is a two-component Gaussian mixture (MotionPrior.h). sigma_R_per_meter models heading drift on straight runs
 * (unequal wheel diameters), which a real robot always has; set it to 0
 * for the paper's pure two-parameter model.
 */
#include <libvslam/models/SE2.h>
#include <mrpt/config/CLoadableOptions.h>

#include <Eigen/Core>
#include <cmath>

namespace vslam
{
class CMotionModel
{
   public:
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		static constexpr const char* kSection = "vslam_motion_model";
		/** Translational noise, m per sqrt(m) travelled. */
		double sigma_T = 0.05;
		/** Rotational noise, rad per sqrt(rad) turned. */
		double sigma_R = 0.1;
		/** Heading drift per distance, rad per sqrt(m) (0: paper model). */
		double sigma_R_per_meter = 0.02;
		/** Probability that one filter update's odometry failed (slip). */
		double slip_probability = 0.02;
		double slip_std_xy = 0.2;  //!< m
		double slip_std_phi = 10 * M_PI / 180;  //!< rad (INI: degrees)

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& cfg,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& cfg,
			const std::string& section) const override;
	};

	CMotionModel() = default;
	explicit CMotionModel(const TOptions& o) : options(o) {}

	TOptions options;

	/** Covariance g(u) of one increment, in the increment's start frame. */
	Eigen::Matrix3d incrementCovariance(const se2::Pose& u) const;
	/** A tiny floor added to every sampled increment's covariance, so the
	 * proposal density is defined when the robot stands still:
	 * diag(1e-4 m, 1e-4 m, 1e-4 rad)^2. */
	Eigen::Matrix3d covarianceFloor() const;
	/** The extra covariance of a slip, diag(slip_std_xy^2, .., slip_std_phi^2). */
	Eigen::Matrix3d slipCovariance() const;
};

}  // namespace vslam

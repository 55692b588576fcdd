#pragma once
/** \file BundleAdjustment.h
 * Small bundle adjustment for landmark creation: a few cameras and up to a
 * few hundred points, reprojection error with a Huber loss, Levenberg-
 * Marquardt on the Schur complement (cameras 6 x n, points 3 x 3 blocks).
 * Camera 0 is held fixed (the gauge); the overall scale is left to the
 * caller, who sets it from odometry.
 */
#include <libvslam/frontend/PinholeCamera.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace vslam::ba
{
/** X_cam = R * X_ref + t. */
struct CameraPose
{
	Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
	Eigen::Vector3d t = Eigen::Vector3d::Zero();

	Eigen::Vector3d map(const Eigen::Vector3d& X) const { return R * X + t; }
	/** The camera centre in the reference frame. */
	Eigen::Vector3d centre() const { return -R.transpose() * t; }
};

struct Observation
{
	int camera = 0, point = 0;
	Eigen::Vector2d pixel;  //!< undistorted
};

/** A prior on one camera's pose (from odometry): residuals
 * log(R R_prior^T) / sigmaRotation and (t - t_prior) / sigmaTranslation. */
struct PosePrior
{
	int camera = 1;
	CameraPose pose;
	double sigmaRotation = 1, sigmaTranslation = 1;  //!< rad, m
};

struct Problem
{
	PinholeCamera camera;
	std::vector<CameraPose> poses;  //!< poses[0] stays fixed
	std::vector<Eigen::Vector3d> points;
	std::vector<Observation> observations;
	std::vector<PosePrior> priors;
};

/** The prior's 6 residuals and their Jacobian wrt [omega, dt] (small-angle
 * approximation of the rotation part, exact at the prior). */
Eigen::Matrix<double, 6, 1> priorResidual(const Problem& problem, const PosePrior& prior);
Eigen::Matrix<double, 6, 6> priorJacobian(const Problem& problem, const PosePrior& prior);

struct TRefineOptions
{
	int iterations = 15;
	double huberPx = 2.0;
};

/** Refines poses[1..] and every point; returns the final robust cost. */
double refine(Problem& problem, const TRefineOptions& options = {});

/** Reprojection residual (pixels) of one observation. */
Eigen::Vector2d residual(const Problem& problem, const Observation& o);

/** Analytic Jacobians of one residual with respect to the camera's
 * perturbation [omega, dt] (X' = exp(omega) X_cam + dt) and to the point. */
void jacobians(
	const Problem& problem, const Observation& o, Eigen::Matrix<double, 2, 6>& Jcam,
	Eigen::Matrix<double, 2, 3>& Jpoint);

/** Applies a camera perturbation [omega, dt]. */
CameraPose perturbed(const CameraPose& pose, const Eigen::Matrix<double, 6, 1>& delta);

/** Linear (DLT) triangulation from two or more views; false if degenerate. */
bool triangulate(
	const PinholeCamera& camera, const std::vector<CameraPose>& poses,
	const std::vector<Eigen::Vector2d>& pixels, Eigen::Vector3d& point);
}  // namespace vslam::ba

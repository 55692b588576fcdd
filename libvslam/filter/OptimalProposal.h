#pragma once
/** \file OptimalProposal.h
 * A Gaussian approximation of the optimal proposal p(s | s_prev, u, z)
 * (FastSLAM 2.0): the pose predicted by odometry, with its covariance,
 * updated by an EKF step with every measurement of the frame that falls
 * inside its validation gate (outliers must not pull the proposal). */
#include <libvslam/filter/CVSlamParticle.h>
#include <libvslam/filter/KnownMeasurement.h>
#include <libvslam/models/CRobustLikelihood.h>
#include <libvslam/models/DualProposal.h>

#include <vector>

namespace vslam
{
/** \param predicted the odometry prediction of the pose
 *  \param predictedCov its covariance (global frame)
 *  \param inGate if given, set to whether each measurement passed its
 *        gate (at the pose updated with the measurements before it). */
PoseGaussianProposal optimalProposal(
	const se2::Pose& predicted, const Eigen::Matrix3d& predictedCov, const LandmarkBank& bank,
	const std::vector<KnownMeasurement>& measurements, const CRobustLikelihood& likelihood,
	std::vector<char>* inGate = nullptr);
}  // namespace vslam

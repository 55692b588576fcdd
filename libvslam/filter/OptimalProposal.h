#pragma once
/** \file OptimalProposal.h
 * A Gaussian approximation of the optimal proposal p(s | s_prev, u, z)
 * (FastSLAM 2.0): the pose predicted by odometry, with its covariance,
 * updated by an EKF step with every measurement of the frame that falls
 * inside its validation gate (outliers must not pull the proposal). */
#include <libvslam/filter/CVSlamParticle.h>
#include <libvslam/filter/KnownMeasurement.h>
#include <libvslam/filter/MotionPrior.h>
#include <libvslam/models/CRobustLikelihood.h>
#include <libvslam/models/DualProposal.h>

#include <vector>

namespace vslam
{
PoseGaussianProposal optimalProposal(
	const se2::Pose& previous, const MotionPrior& motion, const LandmarkBank& bank,
	const std::vector<KnownMeasurement>& measurements, const CRobustLikelihood& likelihood);
}  // namespace vslam

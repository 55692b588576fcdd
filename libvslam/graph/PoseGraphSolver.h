#pragma once
/** \file PoseGraphSolver.h
 * Least squares over a graph of SE(2) poses joined by relative-pose edges:
 * Levenberg-Marquardt on (x, y, phi), a sparse Cholesky (LDLT) per
 * iteration, one node held fixed (the gauge). The residual of an edge i->j
 * is between(x_i, x_j) - z with the angle wrapped; its Jacobians are SE2.h's
 * (each checked against a numerical derivative in SE2_unittest).
 *
 * Written for this project rather than calling MRPT's
 * graphslam::optimize_graph_spa_levmarq: on 2.5.8 that one stalls ("non-
 * definite positive matrix" at every lambda) on small graphs whose edge
 * information spans several orders of magnitude, which is the normal case
 * here (odometry over a few centimetres next to a lost-odometry edge).
 */
#include <libvslam/models/SE2.h>

#include <Eigen/Core>
#include <vector>

namespace vslam
{
struct PoseGraphEdge
{
	size_t from = 0, to = 0;
	/** Pose of node `to` in the frame of node `from`. */
	se2::Pose z{0, 0, 0};
	/** Inverse covariance of z. */
	Eigen::Matrix3d information = Eigen::Matrix3d::Identity();
	/** Huber threshold on the Mahalanobis distance sqrt(chi2): beyond it
	 * the edge's cost grows linearly, not quadratically (0: plain least
	 * squares). */
	double huber = 0;
};

struct PoseGraphSolveReport
{
	size_t iterations = 0;
	double initialCost = 0;  //!< sum of the edges' costs (poseGraphCost) before
	double finalCost = 0;  //!< ... and after
};

/** The edge's residual between(x_from, x_to) - z, angle wrapped. */
Eigen::Vector3d poseGraphResidual(const std::vector<se2::Pose>& nodes, const PoseGraphEdge& e);
/** r' * information * r for that residual. */
double poseGraphChi2(const std::vector<se2::Pose>& nodes, const PoseGraphEdge& e);
/** The edge's cost: its chi-square, or the Huber cost of it (e.huber > 0). */
double poseGraphCost(const std::vector<se2::Pose>& nodes, const PoseGraphEdge& e);

/** Moves every node but `fixedNode` to minimize the sum of the edges'
 * costs (iteratively reweighted for Huber edges); stops after maxIterations or when a step no longer lowers the
 * cost by a relative 1e-9. */
PoseGraphSolveReport solvePoseGraph(
	std::vector<se2::Pose>& nodes, const std::vector<PoseGraphEdge>& edges, size_t fixedNode,
	size_t maxIterations);
}  // namespace vslam

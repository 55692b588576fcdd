#include <libvslam/graph/PoseGraphSolver.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>

using namespace vslam;

Eigen::Vector3d vslam::poseGraphResidual(
	const std::vector<se2::Pose>& nodes, const PoseGraphEdge& e)
{
	return se2::difference(se2::between(nodes[e.from], nodes[e.to]), e.z);
}

double vslam::poseGraphChi2(const std::vector<se2::Pose>& nodes, const PoseGraphEdge& e)
{
	const Eigen::Vector3d r = poseGraphResidual(nodes, e);
	return r.dot(e.information * r);
}

double vslam::poseGraphCost(const std::vector<se2::Pose>& nodes, const PoseGraphEdge& e)
{
	const double chi2 = poseGraphChi2(nodes, e);
	if (e.huber <= 0 || chi2 <= e.huber * e.huber) return chi2;
	return 2 * e.huber * std::sqrt(chi2) - e.huber * e.huber;
}

namespace
{
double totalCost(const std::vector<se2::Pose>& nodes, const std::vector<PoseGraphEdge>& edges)
{
	double cost = 0;
	for (const auto& e : edges) cost += poseGraphCost(nodes, e);
	return cost;
}

/** Column of node n's first variable (the fixed node has none). */
long column(size_t n, size_t fixedNode) { return 3 * static_cast<long>(n < fixedNode ? n : n - 1); }

/** Gauss-Newton system H dx = -g of the current linearization. */
void buildNormalEquations(
	const std::vector<se2::Pose>& nodes, const std::vector<PoseGraphEdge>& edges,
	size_t fixedNode, Eigen::SparseMatrix<double>& H, Eigen::VectorXd& g)
{
	const long n = 3 * static_cast<long>(nodes.size() - 1);
	std::vector<Eigen::Triplet<double>> triplets;
	triplets.reserve(edges.size() * 36);
	g = Eigen::VectorXd::Zero(n);
	// Every diagonal entry is present (a node no edge reaches gets a 0), so
	// damping never changes the pattern and one symbolic analysis serves the
	// whole solve.
	for (long k = 0; k < n; k++) triplets.emplace_back(k, k, 0.0);
	auto addBlock = [&](size_t a, size_t b, const Eigen::Matrix3d& block) {
		if (a == fixedNode || b == fixedNode) return;
		const long ra = column(a, fixedNode), cb = column(b, fixedNode);
		for (int r = 0; r < 3; r++)
			for (int c = 0; c < 3; c++) triplets.emplace_back(ra + r, cb + c, block(r, c));
	};
	for (const auto& e : edges)
	{
		const se2::Pose& xi = nodes[e.from];
		const se2::Pose& xj = nodes[e.to];
		const Eigen::Matrix3d Ji = se2::jacBetweenA(xi, xj), Jj = se2::jacBetweenB(xi, xj);
		const Eigen::Vector3d r = poseGraphResidual(nodes, e);
		// Huber: the weight that makes the quadratic model's gradient the
		// robust cost's (iteratively reweighted least squares).
		const double chi2 = r.dot(e.information * r);
		const double w = e.huber > 0 && chi2 > e.huber * e.huber ? e.huber / std::sqrt(chi2) : 1.0;
		const Eigen::Matrix3d W = w * e.information;
		addBlock(e.from, e.from, Ji.transpose() * W * Ji);
		addBlock(e.from, e.to, Ji.transpose() * W * Jj);
		addBlock(e.to, e.from, Jj.transpose() * W * Ji);
		addBlock(e.to, e.to, Jj.transpose() * W * Jj);
		if (e.from != fixedNode) g.segment<3>(column(e.from, fixedNode)) += Ji.transpose() * W * r;
		if (e.to != fixedNode) g.segment<3>(column(e.to, fixedNode)) += Jj.transpose() * W * r;
	}
	H.resize(n, n);
	H.setFromTriplets(triplets.begin(), triplets.end());
}

std::vector<se2::Pose> stepped(
	const std::vector<se2::Pose>& nodes, const Eigen::VectorXd& dx, size_t fixedNode)
{
	std::vector<se2::Pose> out = nodes;
	for (size_t k = 0; k < nodes.size(); k++)
	{
		if (k == fixedNode) continue;
		const long c = column(k, fixedNode);
		out[k] = {nodes[k].x + dx[c], nodes[k].y + dx[c + 1], se2::wrap(nodes[k].phi + dx[c + 2])};
	}
	return out;
}
}  // namespace

PoseGraphSolveReport vslam::solvePoseGraph(
	std::vector<se2::Pose>& nodes, const std::vector<PoseGraphEdge>& edges, size_t fixedNode,
	size_t maxIterations)
{
	PoseGraphSolveReport report;
	report.initialCost = report.finalCost = totalCost(nodes, edges);
	if (nodes.size() < 2) return report;
	// A node no edge reaches has an empty block: the small constant keeps the
	// damped system definite (its step is then zero).
	constexpr double kDampingFloor = 1e-9;
	double lambda = 1e-4;
	Eigen::SparseMatrix<double> H;
	Eigen::VectorXd g;
	Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
	for (size_t it = 0; it < maxIterations; it++)
	{
		buildNormalEquations(nodes, edges, fixedNode, H, g);
		if (it == 0) solver.analyzePattern(H);
		bool improved = false;
		// Raise the damping until a step lowers the cost (or give up).
		for (int attempt = 0; attempt < 10 && !improved; attempt++)
		{
			Eigen::SparseMatrix<double> damped = H;
			for (long k = 0; k < damped.rows(); k++)
				damped.coeffRef(k, k) += lambda * (H.coeff(k, k) + kDampingFloor);
			solver.factorize(damped);
			if (solver.info() == Eigen::Success)
			{
				const Eigen::VectorXd dx = solver.solve(-g);
				auto candidate = stepped(nodes, dx, fixedNode);
				const double cost = totalCost(candidate, edges);
				if (cost < report.finalCost)
				{
					const double gain = (report.finalCost - cost) / std::max(report.finalCost, 1e-300);
					nodes.swap(candidate);
					report.finalCost = cost;
					lambda = std::max(lambda / 10, 1e-9);
					improved = true;
					report.iterations = it + 1;
					if (gain < 1e-9) return report;
					break;
				}
			}
			lambda *= 10;
		}
		if (!improved) break;
	}
	return report;
}

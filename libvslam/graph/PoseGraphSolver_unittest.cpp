#include <gtest/gtest.h>
#include <libvslam/graph/PoseGraphSolver.h>

#include <cmath>

using namespace vslam;

namespace
{
PoseGraphEdge edge(size_t from, size_t to, const std::vector<se2::Pose>& truth, double stdXY = 0.05,
	double stdPhi = 0.02)
{
	PoseGraphEdge e;
	e.from = from;
	e.to = to;
	e.z = se2::between(truth[from], truth[to]);
	e.information = Eigen::Vector3d(1 / (stdXY * stdXY), 1 / (stdXY * stdXY), 1 / (stdPhi * stdPhi))
						.asDiagonal();
	return e;
}

/** A ring of n poses on a circle of radius 2 m, facing along it, joined
 * to their neighbours and closed from the last to the first. */
std::vector<se2::Pose> ring(size_t n)
{
	std::vector<se2::Pose> p;
	for (size_t k = 0; k < n; k++)
	{
		const double a = 2 * M_PI * static_cast<double>(k) / static_cast<double>(n);
		p.push_back({2 * std::cos(a), 2 * std::sin(a), se2::wrap(a + M_PI / 2)});
	}
	return p;
}

std::vector<PoseGraphEdge> ringEdges(const std::vector<se2::Pose>& truth)
{
	std::vector<PoseGraphEdge> edges;
	for (size_t k = 0; k < truth.size(); k++) edges.push_back(edge(k, (k + 1) % truth.size(), truth));
	return edges;
}

double totalCost(const std::vector<se2::Pose>& nodes, const std::vector<PoseGraphEdge>& edges)
{
	double c = 0;
	for (const auto& e : edges) c += poseGraphCost(nodes, e);
	return c;
}
}  // namespace

TEST(PoseGraphSolver, AConsistentRingIsRecoveredFromAFarGuess)
{
	const auto truth = ring(12);
	const auto edges = ringEdges(truth);
	auto nodes = truth;
	// Up to 0.5 m and 1 rad off (MRPT 2.5.8's SPA stalls on such guesses).
	for (size_t k = 1; k < nodes.size(); k++)
	{
		const double s = std::sin(3.0 * static_cast<double>(k));
		nodes[k] = {nodes[k].x + 0.5 * s, nodes[k].y - 0.4 * s, se2::wrap(nodes[k].phi + 1.0 * s)};
	}
	const auto report = solvePoseGraph(nodes, edges, 0, 100);
	EXPECT_GT(report.initialCost, 1e3);
	EXPECT_LT(report.finalCost, 1e-12);
	for (size_t k = 0; k < nodes.size(); k++)
	{
		EXPECT_NEAR(nodes[k].x, truth[k].x, 1e-6) << k;
		EXPECT_NEAR(nodes[k].y, truth[k].y, 1e-6) << k;
		EXPECT_NEAR(se2::wrap(nodes[k].phi - truth[k].phi), 0, 1e-6) << k;
	}
}

TEST(PoseGraphSolver, TheFixedNodeStaysAndTheGaugeFollowsIt)
{
	const auto truth = ring(6);
	const auto edges = ringEdges(truth);
	auto nodes = truth;
	const se2::Pose shift{0.3, -0.2, 0.1};
	for (auto& n : nodes) n = se2::compose(shift, n);
	nodes[2] = truth[2];  // the fixed node is at its true pose
	solvePoseGraph(nodes, edges, 2, 100);
	for (size_t k = 0; k < nodes.size(); k++)
	{
		EXPECT_NEAR(nodes[k].x, truth[k].x, 1e-6) << k;
		EXPECT_NEAR(nodes[k].y, truth[k].y, 1e-6) << k;
	}
}

TEST(PoseGraphSolver, AnInconsistentRingEndsAtAStationaryPoint)
{
	// The closing edge disagrees by 0.3 m and 10 deg: no exact solution.
	// At the minimum the cost's numerical gradient vanishes, which checks
	// the Jacobians and the normal equations together.
	const auto truth = ring(8);
	auto edges = ringEdges(truth);
	edges.back().z = se2::compose(edges.back().z, {0.3, 0, 10 * M_PI / 180});
	auto nodes = truth;
	const auto report = solvePoseGraph(nodes, edges, 0, 200);
	EXPECT_GT(report.finalCost, 1.0);
	EXPECT_LT(report.finalCost, report.initialCost);
	const double h = 1e-6;
	for (size_t k = 1; k < nodes.size(); k++)
		for (int d = 0; d < 3; d++)
		{
			auto plus = nodes, minus = nodes;
			double* vp[3] = {&plus[k].x, &plus[k].y, &plus[k].phi};
			double* vm[3] = {&minus[k].x, &minus[k].y, &minus[k].phi};
			*vp[d] += h;
			*vm[d] -= h;
			const double grad = (totalCost(plus, edges) - totalCost(minus, edges)) / (2 * h);
			EXPECT_NEAR(grad, 0, 1e-3 * report.finalCost) << "node " << k << " dim " << d;
		}
}

TEST(PoseGraphSolver, AnIrregularNoisyGraphEndsAtAStationaryPoint)
{
	// The normal equations are laid out by blocks once per solve; an
	// irregular graph checks that layout: nodes with many neighbours, edges
	// in both directions and repeated, edges into a fixed node in the
	// middle, a node no edge reaches, every measurement perturbed.
	const auto truth = ring(10);
	std::vector<PoseGraphEdge> edges = ringEdges(truth);
	for (size_t k = 0; k < truth.size(); k++)
	{
		edges.push_back(edge(k, (3 * k + 5) % truth.size(), truth, 0.1, 0.05));
		if (k % 3 == 0) edges.push_back(edge((3 * k + 5) % truth.size(), k, truth, 0.2, 0.03));
	}
	edges.push_back(edge(2, 7, truth));  // a repeat of one above
	for (size_t k = 0; k < edges.size(); k++)
	{
		const double s = std::sin(1.7 * static_cast<double>(k) + 0.3);
		edges[k].z = {edges[k].z.x + 0.05 * s, edges[k].z.y - 0.04 * s,
			se2::wrap(edges[k].z.phi + 0.03 * s)};
	}
	auto nodes = truth;
	nodes.push_back({5, 5, 1});  // no edge reaches it
	const size_t fixedNode = 4;
	const auto report = solvePoseGraph(nodes, edges, fixedNode, 200);
	EXPECT_GT(report.finalCost, 1.0);
	EXPECT_LT(report.finalCost, report.initialCost);
	EXPECT_EQ(nodes[fixedNode].x, truth[fixedNode].x);
	const double h = 1e-6;
	for (size_t k = 0; k < truth.size(); k++)
		for (int d = 0; d < 3; d++)
		{
			if (k == fixedNode) continue;
			auto plus = nodes, minus = nodes;
			double* vp[3] = {&plus[k].x, &plus[k].y, &plus[k].phi};
			double* vm[3] = {&minus[k].x, &minus[k].y, &minus[k].phi};
			*vp[d] += h;
			*vm[d] -= h;
			const double grad = (totalCost(plus, edges) - totalCost(minus, edges)) / (2 * h);
			EXPECT_NEAR(grad, 0, 1e-3 * report.finalCost) << "node " << k << " dim " << d;
		}
	EXPECT_EQ(nodes.back().x, 5);
}

TEST(PoseGraphSolver, AnUnreachedNodeDoesNotBreakTheSolve)
{
	const auto truth = ring(5);
	auto edges = ringEdges(truth);
	auto nodes = truth;
	nodes.push_back({9, 9, 0});  // no edge reaches it
	nodes[3].x += 0.2;
	solvePoseGraph(nodes, edges, 0, 100);
	EXPECT_NEAR(nodes[3].x, truth[3].x, 1e-6);
	EXPECT_DOUBLE_EQ(nodes.back().x, 9);
}

TEST(PoseGraphSolver, HuberEdgesPullLessThanLeastSquares)
{
	// Two edges put node 1 at x = 0, a third at x = 10 (unit information).
	// Least squares: the mean, 3.33. Huber with threshold 1: each of the
	// two pulls with at most 2 * 1 from outside the threshold, so node 1
	// stops inside it, where 2 * 2x = 2, x = 0.5.
	for (const double huber : {0.0, 1.0})
	{
		std::vector<se2::Pose> nodes{{0, 0, 0}, {4, 0, 0}};
		std::vector<PoseGraphEdge> edges(3);
		for (auto& e : edges)
		{
			e.from = 0;
			e.to = 1;
			e.huber = huber;
		}
		edges[2].z = {10, 0, 0};
		const auto report = solvePoseGraph(nodes, edges, 0, 100);
		EXPECT_NEAR(nodes[1].x, huber > 0 ? 0.5 : 10.0 / 3, 1e-5) << "huber " << huber;
		EXPECT_NEAR(report.finalCost, totalCost(nodes, edges) , 1e-9);
	}
}

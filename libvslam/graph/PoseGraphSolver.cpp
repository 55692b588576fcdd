#include <libvslam/graph/PoseGraphSolver.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <cassert>
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

/** The Gauss-Newton system H dx = -g of one solve. Its sparsity depends on
 * the edges only, so it is laid out once per solve: every edge knows where
 * its four 3x3 blocks sit in H's values, and each linearization writes them
 * in place; nothing is sorted or allocated per iteration. Each entry sums
 * its terms in edge order, as assembling it from triplets did. */
class NormalEquations
{
   public:
	NormalEquations(size_t nodeCount, const std::vector<PoseGraphEdge>& edges, size_t fixedNode);

	void linearize(const std::vector<se2::Pose>& nodes, const std::vector<PoseGraphEdge>& edges);

	/** H with lambda * (diag(H) + floor) added to its diagonal, into
	 * `damped`, which has (or is given) H's pattern. */
	void damp(double lambda, double floor, Eigen::SparseMatrix<double>& damped) const;

	const Eigen::SparseMatrix<double>& H() const { return m_H; }
	const Eigen::VectorXd& g() const { return m_g; }

   private:
	/** Where a 3x3 block's three columns start in H's values (the block's
	 * rows follow contiguously); -1: the block touches the fixed node. */
	using BlockOffsets = std::array<long, 3>;
	size_t m_fixed;
	Eigen::SparseMatrix<double> m_H;
	Eigen::VectorXd m_g;
	/** Per block column (a free node), its block rows in order. */
	std::vector<std::vector<int>> m_neighbours;
	/** Per edge: from-from, from-to, to-from, to-to. */
	std::vector<std::array<BlockOffsets, 4>> m_blocks;
	std::vector<long> m_diagonal;

	/** The offsets of the block at (blockRow, blockCol); both are indices
	 * among the free nodes. */
	BlockOffsets blockOffsets(size_t blockRow, size_t blockCol) const;
};

NormalEquations::NormalEquations(
	size_t nodeCount, const std::vector<PoseGraphEdge>& edges, size_t fixedNode)
	: m_fixed(fixedNode)
{
	// The pattern by blocks: block column b holds a block row for each node
	// an edge joins to b, and for b itself, so every diagonal entry is
	// present (a node no edge reaches gets a 0); damping then never changes
	// the pattern and one symbolic analysis serves the whole solve.
	const size_t free = nodeCount - 1;
	const auto blockOf = [fixedNode](size_t node) {
		return static_cast<int>(column(node, fixedNode) / 3);
	};
	m_neighbours.assign(free, {});
	for (size_t b = 0; b < free; b++) m_neighbours[b].push_back(static_cast<int>(b));
	for (const auto& e : edges)
	{
		if (e.from == fixedNode || e.to == fixedNode) continue;
		m_neighbours[static_cast<size_t>(blockOf(e.from))].push_back(blockOf(e.to));
		m_neighbours[static_cast<size_t>(blockOf(e.to))].push_back(blockOf(e.from));
	}
	size_t nonZeros = 0;
	for (auto& rows : m_neighbours)
	{
		std::sort(rows.begin(), rows.end());
		rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
		nonZeros += 9 * rows.size();
	}
	// Compressed column storage written directly: 3 columns per block
	// column, each with the same rows, 3 per block row.
	const long n = 3 * static_cast<long>(free);
	m_H.resize(n, n);
	m_H.resizeNonZeros(static_cast<Eigen::Index>(nonZeros));
	int* outer = m_H.outerIndexPtr();
	int* inner = m_H.innerIndexPtr();
	int at = 0;
	for (size_t b = 0; b < free; b++)
		for (int c = 0; c < 3; c++)
		{
			outer[3 * b + static_cast<size_t>(c)] = at;
			for (const int a : m_neighbours[b])
				for (int r = 0; r < 3; r++) inner[at++] = 3 * a + r;
		}
	outer[n] = at;
	m_g.resize(n);

	m_diagonal.resize(static_cast<size_t>(n));
	for (size_t b = 0; b < free; b++)
	{
		const BlockOffsets d = blockOffsets(b, b);
		for (size_t c = 0; c < 3; c++) m_diagonal[3 * b + c] = d[c] + static_cast<long>(c);
	}
	m_blocks.reserve(edges.size());
	const auto offsets = [&](size_t a, size_t b) -> BlockOffsets {
		if (a == fixedNode || b == fixedNode) return {-1, -1, -1};
		return blockOffsets(static_cast<size_t>(blockOf(a)), static_cast<size_t>(blockOf(b)));
	};
	for (const auto& e : edges)
		m_blocks.push_back({offsets(e.from, e.from), offsets(e.from, e.to), offsets(e.to, e.from),
			offsets(e.to, e.to)});
}

NormalEquations::BlockOffsets NormalEquations::blockOffsets(size_t blockRow, size_t blockCol) const
{
	const auto& rows = m_neighbours[blockCol];
	const auto it = std::lower_bound(rows.begin(), rows.end(), static_cast<int>(blockRow));
	assert(it != rows.end() && *it == static_cast<int>(blockRow));
	const long first = 3 * static_cast<long>(it - rows.begin());
	const int* outer = m_H.outerIndexPtr();
	const size_t col = 3 * blockCol;
	return {outer[col] + first, outer[col + 1] + first, outer[col + 2] + first};
}

void NormalEquations::linearize(
	const std::vector<se2::Pose>& nodes, const std::vector<PoseGraphEdge>& edges)
{
	double* values = m_H.valuePtr();
	std::fill(values, values + m_H.nonZeros(), 0.0);
	m_g.setZero();
	const auto add = [values](const BlockOffsets& at, const Eigen::Matrix3d& block) {
		if (at[0] < 0) return;
		for (int c = 0; c < 3; c++)
			for (int r = 0; r < 3; r++) values[at[static_cast<size_t>(c)] + r] += block(r, c);
	};
	for (size_t k = 0; k < edges.size(); k++)
	{
		const PoseGraphEdge& e = edges[k];
		const se2::Pose& xi = nodes[e.from];
		const se2::Pose& xj = nodes[e.to];
		const Eigen::Matrix3d Ji = se2::jacBetweenA(xi, xj), Jj = se2::jacBetweenB(xi, xj);
		const Eigen::Vector3d r = poseGraphResidual(nodes, e);
		// Huber: the weight that makes the quadratic model's gradient the
		// robust cost's (iteratively reweighted least squares).
		const double chi2 = r.dot(e.information * r);
		const double w = e.huber > 0 && chi2 > e.huber * e.huber ? e.huber / std::sqrt(chi2) : 1.0;
		const Eigen::Matrix3d W = w * e.information;
		const auto& blocks = m_blocks[k];
		add(blocks[0], Ji.transpose() * W * Ji);
		add(blocks[1], Ji.transpose() * W * Jj);
		add(blocks[2], Jj.transpose() * W * Ji);
		add(blocks[3], Jj.transpose() * W * Jj);
		if (e.from != m_fixed) m_g.segment<3>(column(e.from, m_fixed)) += Ji.transpose() * W * r;
		if (e.to != m_fixed) m_g.segment<3>(column(e.to, m_fixed)) += Jj.transpose() * W * r;
	}
}

void NormalEquations::damp(
	double lambda, double floor, Eigen::SparseMatrix<double>& damped) const
{
	if (damped.nonZeros() != m_H.nonZeros())
		damped = m_H;  // the pattern, once per solve
	else
		std::copy(m_H.valuePtr(), m_H.valuePtr() + m_H.nonZeros(), damped.valuePtr());
	const double* h = m_H.valuePtr();
	double* d = damped.valuePtr();
	for (const long k : m_diagonal) d[k] += lambda * (h[k] + floor);
}

void stepInto(const std::vector<se2::Pose>& nodes, const Eigen::VectorXd& dx, size_t fixedNode,
	std::vector<se2::Pose>& out)
{
	out = nodes;
	for (size_t k = 0; k < nodes.size(); k++)
	{
		if (k == fixedNode) continue;
		const long c = column(k, fixedNode);
		out[k] = {nodes[k].x + dx[c], nodes[k].y + dx[c + 1], se2::wrap(nodes[k].phi + dx[c + 2])};
	}
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
	NormalEquations system(nodes.size(), edges, fixedNode);
	Eigen::SparseMatrix<double> damped;
	Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
	std::vector<se2::Pose> candidate;
	for (size_t it = 0; it < maxIterations; it++)
	{
		system.linearize(nodes, edges);
		if (it == 0) solver.analyzePattern(system.H());
		bool improved = false;
		// Raise the damping until a step lowers the cost (or give up).
		for (int attempt = 0; attempt < 10 && !improved; attempt++)
		{
			system.damp(lambda, kDampingFloor, damped);
			solver.factorize(damped);
			if (solver.info() == Eigen::Success)
			{
				const Eigen::VectorXd dx = solver.solve(-system.g());
				stepInto(nodes, dx, fixedNode, candidate);
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

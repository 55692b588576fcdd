#include <libvslam/config/StrictRead.h>
#include <libvslam/graph/CLandmarkPoseGraph.h>
#include <libvslam/models/CLandmarkModel.h>
#include <libvslam/models/ChiSquare.h>

#include <Eigen/LU>
#include <algorithm>
#include <stdexcept>

using namespace vslam;
using namespace vslam::config;

namespace
{
/** Variance standing in for "no information" after a kidnap [m^2], [rad^2]. */
constexpr double kLostOdometryVarXY = 1e2;
constexpr double kLostOdometryVarPhi = 10;
/** Keeps a near-singular covariance (a robot standing still) invertible. */
constexpr double kCovarianceFloor = 1e-6;
/** Levenberg-Marquardt iterations per solve: the graphs converge in far fewer. */
constexpr uint32_t kMaxIterations = 50;
/** A point landmark is a pose node whose heading nothing measures: its
 * edges carry this variance on the heading [rad^2], which keeps the
 * normal equations definite and moves nothing else (its cost is at most
 * pi^2 / 1e6). */
constexpr double kUnmeasuredHeadingVar = 1e6;

/** A measurement as an edge from the robot's keyframe to the landmark:
 * the landmark frame in the robot frame (pose kind), or the point in the
 * robot frame with its range-bearing noise carried through (point kind). */
std::pair<se2::Pose, Eigen::Matrix3d> edgeOf(const LandmarkMeasurement& m)
{
	if (m.kind() == LandmarkKind::Pose) return {{m.z[0], m.z[1], m.z[2]}, Eigen::Matrix3d(m.R)};
	const LandmarkEstimate inRobot = landmarkModel(LandmarkKind::Point).initialize({0, 0, 0}, m);
	Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
	cov.topLeftCorner<2, 2>() = inRobot.cov.topLeftCorner<2, 2>();
	cov(2, 2) = kUnmeasuredHeadingVar;
	return {{inRobot.mean[0], inRobot.mean[1], 0}, cov};
}
}  // namespace

void CLandmarkPoseGraph::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	enabled = readBool(c, s, "enabled", enabled);
	min_gap_s = readDouble(c, s, "min_gap_s", min_gap_s, Range::nonNegative());
	edge_gate_probability = readDouble(
		c, s, "edge_gate_probability", edge_gate_probability, Range{0, 1, false, false});
	max_keyframes = static_cast<uint32_t>(
		readInt(c, s, "max_keyframes", max_keyframes, Range::closed(0, 1e8)));
}

void CLandmarkPoseGraph::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "enabled", enabled, 25, 12,
		"Optimize the pose graph of the run on loop closures and move the particles onto it");
	c.write(s, "min_gap_s", min_gap_s, 25, 12,
		"A landmark measured again after this long [s] closes a loop");
	c.write(s, "edge_gate_probability", edge_gate_probability, 25, 12,
		"Chi-square gate that keeps a measurement edge after an optimization");
	c.write(s, "max_keyframes", static_cast<int>(max_keyframes), 25, 12,
		"Keyframes kept at most; beyond, every second one of the older half goes (0: no limit)");
}

CLandmarkPoseGraph::CLandmarkPoseGraph(const TOptions& options, const se2::Pose& start)
	: m_options(options), m_nodes{start}
{
}

void CLandmarkPoseGraph::addOdometry(const se2::Pose& u, const Eigen::Matrix3d& cov)
{
	m_odometry.add(u, cov);
}

void CLandmarkPoseGraph::loseOdometry() { m_odometryLost = true; }

size_t CLandmarkPoseGraph::addNode(const se2::Pose& guess)
{
	m_nodes.push_back(guess);
	return m_nodes.size() - 1;
}

void CLandmarkPoseGraph::addEdge(size_t from, size_t to, const se2::Pose& z, const Eigen::Matrix3d& cov,
	EdgeKind kind, LandmarkKind landmark)
{
	PoseGraphEdge e;
	e.from = from;
	e.to = to;
	e.z = z;
	e.information = (cov + kCovarianceFloor * Eigen::Matrix3d::Identity()).inverse();
	m_edges.push_back(e);
	m_edgeStates.push_back({kind, true, static_cast<uint8_t>(stateDim(landmark))});
}

void CLandmarkPoseGraph::addKeyframe(mrpt::Clock::time_point t, const se2::Pose& guess)
{
	const size_t node = addNode(guess);
	Eigen::Matrix3d cov = m_odometry.cov();
	if (m_odometryLost)
		cov = Eigen::Vector3d(kLostOdometryVarXY, kLostOdometryVarXY, kLostOdometryVarPhi)
				  .asDiagonal();
	addEdge(m_lastKeyframeNode, node, m_odometry.mean(), cov, EdgeKind::Odometry);
	m_odometry.reset();
	m_odometryLost = false;
	m_lastKeyframeNode = node;
	m_keyframe = t;
	m_keyframeNodes.emplace_back(t, node);
	if (m_options.max_keyframes > 0 && m_keyframeNodes.size() > m_options.max_keyframes)
		thinKeyframes();
}

std::vector<std::pair<mrpt::Clock::time_point, se2::Pose>> CLandmarkPoseGraph::keyframePath() const
{
	std::vector<std::pair<mrpt::Clock::time_point, se2::Pose>> path;
	path.reserve(m_keyframeNodes.size());
	for (const auto& [t, node] : m_keyframeNodes) path.emplace_back(t, m_nodes[node]);
	return path;
}

void CLandmarkPoseGraph::placeLandmark(size_t slot, const LandmarkMeasurement& m)
{
	if (!m_keyframe) throw std::logic_error("CLandmarkPoseGraph: landmark before any keyframe");
	const auto [z, cov] = edgeOf(m);
	const size_t node = addNode(se2::compose(m_nodes[m_lastKeyframeNode], z));
	addEdge(m_lastKeyframeNode, node, z, cov, EdgeKind::Creation, m.kind());
	m_landmarks[slot] = {node, *m_keyframe, m.kind()};
}

bool CLandmarkPoseGraph::addMeasurement(size_t slot, const LandmarkMeasurement& m)
{
	if (!m_keyframe) throw std::logic_error("CLandmarkPoseGraph: measurement before any keyframe");
	auto& landmark = m_landmarks.at(slot);
	const auto [z, cov] = edgeOf(m);
	addEdge(m_lastKeyframeNode, landmark.node, z, cov, EdgeKind::Measurement, m.kind());
	const double gap = std::chrono::duration<double>(*m_keyframe - landmark.lastSeen).count();
	landmark.lastSeen = *m_keyframe;
	return gap >= m_options.min_gap_s;
}

bool CLandmarkPoseGraph::reviseOutliers()
{
	// An edge's chi-square over its gate: a pose measures 3 values, a point 2.
	const double gates[4] = {0, 0, chiSquareQuantile(m_options.edge_gate_probability, 2),
		chiSquareQuantile(m_options.edge_gate_probability, 3)};
	const auto overGate = [&](size_t k) { return poseGraphChi2(m_nodes, m_edges[k]) / gates[m_edgeStates[k].dof]; };
	// Bring back every edge the solution now explains ...
	bool changed = false;
	for (size_t k = 0; k < m_edges.size(); k++)
		if (m_edgeStates[k].kind == EdgeKind::Measurement && !m_edgeStates[k].active && overGate(k) <= 1)
			m_edgeStates[k].active = true, changed = true;
	if (changed) return true;
	// ... else leave out the one it explains worst, if outside the gate.
	std::optional<size_t> worst;
	double worstRatio = 1;
	for (size_t k = 0; k < m_edges.size(); k++)
	{
		if (m_edgeStates[k].kind != EdgeKind::Measurement || !m_edgeStates[k].active) continue;
		const double ratio = overGate(k);
		if (ratio > worstRatio) worst = k, worstRatio = ratio;
	}
	if (!worst) return false;
	m_edgeStates[*worst].active = false;
	return true;
}

CLandmarkPoseGraph::Correction CLandmarkPoseGraph::optimize()
{
	if (!m_keyframe) throw std::logic_error("CLandmarkPoseGraph: optimize before any keyframe");
	Correction out;
	// Solve with the edges in, revise which measurements are in, solve
	// again. Left out one at a time, worst first: while an outlier is in,
	// it pulls its neighbours' edges out of the gate too. Nothing is left
	// out for good: an edge a later solution explains comes back.
	constexpr size_t kMaxRevisions = 10;
	std::vector<PoseGraphEdge> active;
	for (size_t revision = 0;; revision++)
	{
		active.clear();
		for (size_t k = 0; k < m_edges.size(); k++)
			if (m_edgeStates[k].active) active.push_back(m_edges[k]);
		const PoseGraphSolveReport report = solvePoseGraph(m_nodes, active, 0, kMaxIterations);
		out.chi2 = report.finalCost;
		out.iterations += report.iterations;
		if (revision == kMaxRevisions || !reviseOutliers()) break;
	}
	out.leftOutEdges = static_cast<size_t>(std::count_if(
		m_edgeStates.begin(), m_edgeStates.end(), [](const EdgeState& s) { return !s.active; }));
	out.keyframe = m_nodes[m_lastKeyframeNode];
	out.landmarks.reserve(m_landmarks.size());
	for (const auto& [slot, landmark] : m_landmarks)
		out.landmarks.push_back({slot, landmark.kind, m_nodes[landmark.node]});
	return out;
}

#include <libvslam/config/StrictRead.h>
#include <libvslam/graph/CLandmarkPoseGraph.h>
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

void CLandmarkPoseGraph::addEdge(
	size_t from, size_t to, const se2::Pose& z, const Eigen::Matrix3d& cov, EdgeKind kind)
{
	PoseGraphEdge e;
	e.from = from;
	e.to = to;
	e.z = z;
	e.information = (cov + kCovarianceFloor * Eigen::Matrix3d::Identity()).inverse();
	m_edges.push_back(e);
	m_edgeStates.push_back({kind, true});
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
	const se2::Pose z{m.z[0], m.z[1], m.z[2]};
	const size_t node = addNode(se2::compose(m_nodes[m_lastKeyframeNode], z));
	addEdge(m_lastKeyframeNode, node, z, Eigen::Matrix3d(m.R), EdgeKind::Creation);
	m_landmarks[slot] = {node, *m_keyframe};
}

bool CLandmarkPoseGraph::addMeasurement(size_t slot, const LandmarkMeasurement& m)
{
	if (!m_keyframe) throw std::logic_error("CLandmarkPoseGraph: measurement before any keyframe");
	auto& landmark = m_landmarks.at(slot);
	addEdge(m_lastKeyframeNode, landmark.node, {m.z[0], m.z[1], m.z[2]}, Eigen::Matrix3d(m.R),
		EdgeKind::Measurement);
	const double gap = std::chrono::duration<double>(*m_keyframe - landmark.lastSeen).count();
	landmark.lastSeen = *m_keyframe;
	return gap >= m_options.min_gap_s;
}

bool CLandmarkPoseGraph::reviseOutliers()
{
	const double gate = chiSquareQuantile(m_options.edge_gate_probability, 3);
	// Bring back every edge the solution now explains ...
	bool changed = false;
	for (size_t k = 0; k < m_edges.size(); k++)
		if (m_edgeStates[k].kind == EdgeKind::Measurement && !m_edgeStates[k].active &&
			poseGraphChi2(m_nodes, m_edges[k]) <= gate)
			m_edgeStates[k].active = true, changed = true;
	if (changed) return true;
	// ... else leave out the one it explains worst, if outside the gate.
	std::optional<size_t> worst;
	double worstChi2 = gate;
	for (size_t k = 0; k < m_edges.size(); k++)
	{
		if (m_edgeStates[k].kind != EdgeKind::Measurement || !m_edgeStates[k].active) continue;
		const double chi2 = poseGraphChi2(m_nodes, m_edges[k]);
		if (chi2 > worstChi2) worst = k, worstChi2 = chi2;
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
		out.chi2 = solvePoseGraph(m_nodes, active, 0, kMaxIterations).finalCost;
		if (revision == kMaxRevisions || !reviseOutliers()) break;
	}
	out.leftOutEdges = static_cast<size_t>(std::count_if(
		m_edgeStates.begin(), m_edgeStates.end(), [](const EdgeState& s) { return !s.active; }));
	out.keyframe = m_nodes[m_lastKeyframeNode];
	out.landmarks.reserve(m_landmarks.size());
	for (const auto& [slot, landmark] : m_landmarks)
		out.landmarks.emplace_back(slot, m_nodes[landmark.node]);
	return out;
}

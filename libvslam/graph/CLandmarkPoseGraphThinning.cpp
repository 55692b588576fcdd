/** \file CLandmarkPoseGraphThinning.cpp
 * Keeps the pose graph within TOptions::max_keyframes (CLandmarkPoseGraph.h).
 *
 * Of the older half of the keyframes, every second one that no landmark was
 * created from goes. Its measurement edges go with it (their information is
 * lost, never counted twice), and the odometry edges into and out of it
 * become one edge: the composed increment, its covariance propagated to
 * first order (COdometryAccumulator), exactly what the odometry would have
 * given had no keyframe been taken there. Each thinning halves the density
 * of the older half, so the density falls with age and the count stays
 * below the cap, give or take the landmark anchors (bounded by the map).
 */
#include <libvslam/graph/CLandmarkPoseGraph.h>

#include <Eigen/LU>
#include <unordered_map>
#include <unordered_set>

using namespace vslam;

void CLandmarkPoseGraph::thinKeyframes()
{
	// Keyframes that must stay: a landmark's creation hangs from them.
	std::unordered_set<size_t> anchors;
	for (size_t k = 0; k < m_edges.size(); k++)
		if (m_edgeStates[k].kind == EdgeKind::Creation) anchors.insert(m_edges[k].from);
	std::vector<char> removed(m_nodes.size(), 0);
	const size_t olderHalf = m_keyframeNodes.size() / 2;
	bool skip = false;
	for (size_t i = 0; i < olderHalf; i++)
	{
		const size_t node = m_keyframeNodes[i].second;
		if (anchors.count(node)) continue;
		if (!skip) removed[node] = 1;
		skip = !skip;
	}

	// The odometry chain: each keyframe's incoming odometry edge.
	std::unordered_map<size_t, size_t> incomingOdometry;
	for (size_t k = 0; k < m_edges.size(); k++)
		if (m_edgeStates[k].kind == EdgeKind::Odometry) incomingOdometry[m_edges[k].to] = k;

	// New node numbering, and the edges that stay or are composed.
	std::vector<size_t> newIndex(m_nodes.size());
	std::vector<se2::Pose> nodes;
	nodes.reserve(m_nodes.size());
	for (size_t n = 0; n < m_nodes.size(); n++)
		if (!removed[n]) newIndex[n] = nodes.size(), nodes.push_back(m_nodes[n]);
	std::vector<PoseGraphEdge> edges;
	std::vector<EdgeState> states;
	for (size_t k = 0; k < m_edges.size(); k++)
	{
		const PoseGraphEdge& e = m_edges[k];
		if (removed[e.to]) continue;  // odometry into a removed keyframe: composed below
		if (m_edgeStates[k].kind == EdgeKind::Odometry && removed[e.from])
		{
			// Walk back over the removed keyframes to the kept one before them,
			// and compose the odometry from there.
			std::vector<size_t> segment{k};
			size_t from = e.from;
			while (removed[from])
			{
				segment.push_back(incomingOdometry.at(from));
				from = m_edges[segment.back()].from;
			}
			COdometryAccumulator chain;
			for (auto it = segment.rbegin(); it != segment.rend(); ++it)
				chain.add(m_edges[*it].z, m_edges[*it].information.inverse());
			PoseGraphEdge composed = e;
			composed.from = from;
			composed.z = chain.mean();
			composed.information = chain.cov().inverse();
			edges.push_back(composed);
			states.push_back(m_edgeStates[k]);
			continue;
		}
		if (removed[e.from]) continue;  // a removed keyframe's measurement
		edges.push_back(e);
		states.push_back(m_edgeStates[k]);
	}
	for (auto& e : edges) e.from = newIndex[e.from], e.to = newIndex[e.to];

	std::vector<std::pair<mrpt::Clock::time_point, size_t>> keyframeNodes;
	for (const auto& [t, node] : m_keyframeNodes)
		if (!removed[node]) keyframeNodes.emplace_back(t, newIndex[node]);
	for (auto& [slot, landmark] : m_landmarks) landmark.node = newIndex[landmark.node];
	m_lastKeyframeNode = newIndex[m_lastKeyframeNode];
	m_nodes.swap(nodes);
	m_edges.swap(edges);
	m_edgeStates.swap(states);
	m_keyframeNodes.swap(keyframeNodes);
}

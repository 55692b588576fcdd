#include <libvslam/graph/CLandmarkPoseGraph.h>

using namespace vslam;

mrpt::graphs::CNetworkOfPoses2DInf CLandmarkPoseGraph::toMrptGraph() const
{
	mrpt::graphs::CNetworkOfPoses2DInf graph;
	graph.root = 0;
	for (size_t i = 0; i < m_nodes.size(); i++)
		graph.nodes[i] = mrpt::poses::CPose2D(m_nodes[i].x, m_nodes[i].y, m_nodes[i].phi);
	for (size_t k = 0; k < m_edges.size(); k++)
	{
		if (!m_edgeStates[k].active) continue;
		const PoseGraphEdge& e = m_edges[k];
		mrpt::poses::CPosePDFGaussianInf z;
		z.mean = mrpt::poses::CPose2D(e.z.x, e.z.y, e.z.phi);
		z.cov_inv = mrpt::math::CMatrixDouble33(e.information);
		graph.insertEdge(e.from, e.to, z);
	}
	return graph;
}

#pragma once
/** \file CLandmarkPoseGraph.h
 * The loop-closure back-end: the whole run as a pose graph, optimized when a
 * loop closes, so the particle filter can continue on a straightened map.
 *
 * A visual landmark is a frame (the robot pose it was created at) and its
 * measurement is that frame in the robot frame: a relative pose. With the
 * front-end's landmark IDs the data association is known, so the run is a
 * graph of SE(2) nodes (keyframes = robot poses of frames that measured a
 * landmark, and landmarks) joined by odometry edges between consecutive
 * keyframes and by one edge per measurement. The particle filter alone keeps
 * the error of a map built while no older landmark was in view: every
 * particle's map is consistent with its own path, resampling keeps a single
 * lineage, and a loop closure can then only pull the robot back and forth
 * between the old and the new part of the map. The graph's least-squares
 * solution (PoseGraphSolver.h) spreads that error over the loop.
 *
 * Gauge: the start pose (node 0) is fixed, as the filter's initial pose is.
 * Outliers: after a solve, left-out measurement edges the solution explains
 * come back, or else the one with the largest chi-square is left out if it
 * exceeds a gate, and the graph is solved again (up to 10 revisions per
 * optimization; nothing is left out for good).
 * Point (range-bearing) landmarks take part as nodes whose heading nothing
 * measures: a measurement is the point in the robot frame, with the range
 * and bearing noise carried through, and no information on the heading.
 * One solver then serves both kinds, and a run may mix them.
 *
 * Bounded size: every frame with a measurement adds a keyframe, so a long
 * run would make every solve, and the run, ever slower. Past
 * `max_keyframes`, every second keyframe of the older half goes
 * (CLandmarkPoseGraphThinning.cpp): its measurement edges are dropped and
 * the odometry edges on either side become one. Keyframes a landmark was
 * created from stay. The older a part of the run, the sparser its
 * keyframes, and the graph stays within the cap, give or take those
 * anchors (as many as the map has landmarks).
 */
#include <libvslam/graph/PoseGraphSolver.h>
#include <libvslam/models/COdometryAccumulator.h>
#include <libvslam/models/LandmarkTypes.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/graphs/CNetworkOfPoses.h>
#include <mrpt/system/datetime.h>

#include <optional>
#include <map>
#include <string>
#include <vector>

namespace vslam
{
class CLandmarkPoseGraph
{
   public:
	/** [vslam_loop_closure] */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		static constexpr const char* kSection = "vslam_loop_closure";
		/** Build the graph and correct the filter on loop closures. */
		bool enabled = true;
		/** A measurement closes a loop when its landmark was last measured
		 * (or created) at least this long ago [s]. */
		double min_gap_s = 20;
		/** Probability mass of the chi-square gate that keeps a measurement
		 * edge after an optimization, (0,1). */
		double edge_gate_probability = 0.999;
		/** Keyframes kept at most: beyond, the older half is thinned
		 * (0: no limit). */
		uint32_t max_keyframes = 2000;

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& cfg,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& cfg,
			const std::string& section) const override;
	};

	/** The optimized poses the filter moves to. */
	struct Correction
	{
		/** The latest keyframe (the robot pose of the current frame). */
		se2::Pose keyframe{0, 0, 0};
		struct Landmark
		{
			size_t slot = 0;
			LandmarkKind kind = LandmarkKind::Pose;
			se2::Pose pose{0, 0, 0};  //!< a point's heading means nothing
		};
		/** Every landmark slot in the graph, with its pose. */
		std::vector<Landmark> landmarks;
		/** Measurement edges the gate leaves out of this solution. */
		size_t leftOutEdges = 0;
		/** The solution's cost: the sum over the edges in it (PoseGraphSolver.h). */
		double chi2 = 0;
		/** Levenberg-Marquardt iterations, over every revision of the edges. */
		size_t iterations = 0;
	};

	CLandmarkPoseGraph(const TOptions& options, const se2::Pose& start);

	/** Odometry since the last call (mean and covariance in its start frame). */
	void addOdometry(const se2::Pose& u, const Eigen::Matrix3d& cov);
	/** The odometry since the last keyframe says nothing (kidnap): the next
	 * keyframe is tied to the previous one only by a very weak edge. */
	void loseOdometry();

	/** Starts a keyframe at time t with the filter's pose as first guess,
	 * joined to the previous keyframe by the odometry since then. */
	void addKeyframe(mrpt::Clock::time_point t, const se2::Pose& guess);
	bool hasKeyframe() const { return m_keyframe.has_value(); }

	/** A landmark created (or re-created) in slot from the current keyframe:
	 * a new node, whose pose in the keyframe is m.z with covariance m.R.
	 * A re-created slot leaves its old node and edges behind. */
	void placeLandmark(size_t slot, const LandmarkMeasurement& m);
	/** A measurement of the landmark in slot from the current keyframe.
	 * Returns true if it closes a loop (see TOptions::min_gap_s). */
	bool addMeasurement(size_t slot, const LandmarkMeasurement& m);
	bool hasLandmark(size_t slot) const { return m_landmarks.count(slot) > 0; }

	/** Optimizes the whole graph (start pose fixed), drops measurement edges
	 * outside the gate and optimizes again. Needs a keyframe. */
	Correction optimize();

	/** Every keyframe's time and current pose (after optimize(): the
	 * smoothed path of the whole run). */
	std::vector<std::pair<mrpt::Clock::time_point, se2::Pose>> keyframePath() const;

	size_t keyframes() const { return m_keyframeNodes.size(); }
	/** The graph as MRPT's network of poses (keyframes and landmarks as
	 * nodes, the edges in use with their information; node 0, the start, is
	 * the root): `graph-slam --view -i` shows its saveToTextFile(). */
	mrpt::graphs::CNetworkOfPoses2DInf toMrptGraph() const;
	size_t edges() const { return m_edges.size(); }
	size_t nodes() const { return m_nodes.size(); }

   private:
	struct LandmarkNode
	{
		size_t node;
		mrpt::Clock::time_point lastSeen;
		LandmarkKind kind = LandmarkKind::Pose;
	};

	TOptions m_options;
	/** Node 0 is the start pose (fixed); then keyframes and landmarks. */
	std::vector<se2::Pose> m_nodes;
	std::vector<PoseGraphEdge> m_edges;
	enum class EdgeKind : uint8_t
	{
		Odometry,  //!< between consecutive keyframes (node 0 first)
		Creation,  //!< a keyframe to the landmark created from it
		Measurement  //!< a keyframe to a landmark it measured: gated
	};
	/** Per edge (same index as m_edges): its kind, and whether it is in the
	 * current solution (the gate may leave measurements out). */
	struct EdgeState
	{
		EdgeKind kind = EdgeKind::Odometry;
		bool active = true;
		uint8_t dof = 3;  //!< values the edge measures (its chi-square gate's)
	};
	std::vector<EdgeState> m_edgeStates;
	size_t m_lastKeyframeNode = 0;
	std::optional<mrpt::Clock::time_point> m_keyframe;
	COdometryAccumulator m_odometry;
	bool m_odometryLost = false;
	std::vector<std::pair<mrpt::Clock::time_point, size_t>> m_keyframeNodes;
	std::map<size_t, LandmarkNode> m_landmarks;

	size_t addNode(const se2::Pose& guess);
	/** Adds an edge from `from` to `to`, measuring z with covariance cov. */
	void addEdge(size_t from, size_t to, const se2::Pose& z, const Eigen::Matrix3d& cov, EdgeKind kind,
		LandmarkKind landmark = LandmarkKind::Pose);
	/** Removes every second keyframe of the older half (see the file
	 * comment); CLandmarkPoseGraphThinning.cpp. */
	void thinKeyframes();
	/** After a solve: brings back the left-out edges the solution explains,
	 * or else leaves out the worst edge outside the gate; false if nothing
	 * changed. */
	bool reviseOutliers();
};
}  // namespace vslam

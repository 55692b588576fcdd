#include <libvslam/core/InputError.h>
#include <libvslam/io/RawlogWriting.h>
#include <libvslam/io/Trajectory.h>
#include <libvslam/sim/SimulatedRunFiles.h>

#include <cstdio>

namespace vslam
{
void writeSimulatedRawlog(const SimulatedRun& run, const std::string& rawlogFile)
{
	std::vector<ActionFramePair> steps;
	for (const auto& st : run.steps) steps.emplace_back(st.action, st.sf);
	writeActionFrameRawlog(rawlogFile, steps);
}

void writeSimulatedGroundTruth(const SimulatedRun& run, const std::string& tumFile)
{
	Trajectory tr;
	for (const auto& st : run.steps) tr.push_back({mrpt::Clock::toDouble(st.t), st.truePose});
	writeTumTrajectory(tumFile, tr);
}

void writeSimulatedLandmarks(const SimulatedRun& run, const std::string& file)
{
	FILE* f = std::fopen(file.c_str(), "wt");
	if (!f) throw InputError("cannot create '" + file + "'");
	std::fprintf(f, "%% id kind x y phi mapped_before_recording\n");
	for (const auto& l : run.landmarks)
		std::fprintf(f, "%lld %s %.6f %.6f %.6f %d\n", static_cast<long long>(l.key.id),
			toString(l.key.kind), l.pose.x, l.pose.y, l.pose.phi, l.mappedBeforeRecording ? 1 : 0);
	std::fclose(f);
}

}  // namespace vslam

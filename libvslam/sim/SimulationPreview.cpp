#include <libvslam/eval/TrajectoryPlot.h>
#include <libvslam/sim/CVisualSimulator.h>

namespace vslam
{
void writeSimulationPreview(const world::FloorPlan& plan, const VisualSimRun& run, const std::string& pngFile)
{
	PlotSeries odometry{&run.odometryPath, {220, 0, 0}, "odometry (dead reckoning)", {}};
	PlotSeries truth{&run.truePath, {0, 160, 0}, "true path (kidnaps in blue)", {}};
	for (size_t k : run.kidnapSteps) truth.jumps.push_back(k - 1);  // entry k - 1 is step k
	writeTrajectoryPlot(&plan, {odometry, truth}, pngFile);
}
}  // namespace vslam

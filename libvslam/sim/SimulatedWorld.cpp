#include <libvslam/sim/SimulatedWorld.h>
#include <libvslam/world/FloorPlanFile.h>
#include <libvslam/world/HomeGenerator.h>

#include <cmath>

namespace vslam
{
SimulatedWorld loadSimulatedWorld(CVisualSimulator::TOptions& o)
{
	SimulatedWorld w;
	if (o.world_seed == 0)
	{
		w.plan = world::loadFloorPlan(o.world_file, o.texture_dir);
		return w;
	}
	world::GeneratedHome home = world::generateHome(o.world_seed, o.texture_dir);
	o.start_pose = {home.start.x, home.start.y, home.start.phi * 180 / M_PI};
	w.plan = std::move(home.plan);
	w.generatedText = std::move(home.worldText);
	return w;
}
}  // namespace vslam

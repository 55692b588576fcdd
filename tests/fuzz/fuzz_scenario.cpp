/** Fuzz target: vslam-simul's scenario files. Input: the INI text (section
 * [vslam_simul]) and a world file, separated by a line "%%%%". The INI is
 * loaded with its world_file pointed at the fuzzed world; the world is
 * parsed (textures from /usr/share) and the simulator validates the start,
 * the waypoint legs and the people's walks against it. Any outcome but a
 * valid scenario, a ConfigError or an InputError is a finding. Rendering
 * is not fuzzed (its inputs are the validated world and options). */
#include <libvslam/config/ConfigError.h>
#include <libvslam/core/InputError.h>
#include <libvslam/sim/CVisualSimulator.h>
#include <libvslam/world/FloorPlanFile.h>
#include <tests/fuzz/FuzzInput.h>

#include <fstream>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	static const std::string dir = vslam::fuzz::scratchPath("scenario");
	std::filesystem::create_directories(dir);
	const auto parts = vslam::fuzz::splitAtLines(data, size, "%%%%");
	const std::string world = dir + "/fuzz.world";
	std::ofstream(world, std::ios::trunc) << (parts.size() > 1 ? parts[1] : std::string());
	try
	{
		const auto options = vslam::loadVisualSimOptions(
			parts.empty() ? std::string() : parts[0], {{"vslam_simul", "world_file", world}}, dir);
		const auto plan = vslam::world::loadFloorPlan(options.world_file, options.texture_dir);
		vslam::CVisualSimulator simulator(options, plan);
	}
	catch (const vslam::ConfigError&)
	{
	}
	catch (const vslam::InputError&)
	{
	}
	return 0;
}

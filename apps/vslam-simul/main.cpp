/** vslam-simul: a rendered indoor world with camera, odometry, laser and
 * ground truth, written as an MRPT rawlog.
 *
 *   vslam-simul CONFIG.ini OUTPUT.rawlog [--set vslam_simul.KEY=VALUE ...] [--quiet]
 *
 * Reads [vslam_simul] (see config_ini/simul_example.ini) and writes
 * OUTPUT.rawlog (actions/sensory frames: odometry, a 2-D laser scan every
 * step, a camera image every few steps; vslam and rbpf-slam read it),
 * the images in OUTPUT_Images/, OUTPUT_groundtruth.tum (true path),
 * OUTPUT_odometry.tum (dead reckoning) and OUTPUT_preview.png. */
#include <libvslam/app/ToolArguments.h>
#include <libvslam/app/ToolMain.h>
#include <libvslam/config/ConfigError.h>
#include <libvslam/config/ConfigReference.h>
#include <libvslam/config/StrictRead.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <libvslam/config/IniText.h>
#include <libvslam/config/Overrides.h>
#include <libvslam/io/CRawlogReader.h>
#include <libvslam/sim/CVisualSimulator.h>
#include <libvslam/sim/SimulatedWorld.h>
#include <libvslam/world/FloorPlanFile.h>
#include <libvslam/world/FurnitureCatalog.h>
#include <mrpt/system/CTicTac.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace
{
const char* kUsage =
	"Usage: vslam-simul CONFIG.ini OUTPUT.rawlog [--set vslam_simul.KEY=VALUE ...] [--quiet]\n"
	"       vslam-simul --print-default-config [--markdown]\n"
	"       vslam-simul --list-furniture\n";
}

int main(int argc, const char** argv)
{
	using namespace vslam;
	return vslam::runTool("vslam-simul", kUsage, [&]() -> int {
		const ToolArguments args =
			parseToolArguments(argc, argv, {}, {"--help", "--print-default-config", "--markdown", "--list-furniture", "--quiet"});
		if (args.has("--help"))
		{
			std::cout << kUsage;
			return 0;
		}
		if (args.has("--list-furniture"))
		{
			// The names a world file's "furniture" item takes, with their sizes.
			std::printf("%-24s %7s %7s %7s %9s  model (under texture_dir)\n", "name", "width", "depth", "height", "elevation");
			for (const auto& item : world::furnitureCatalog())
				std::printf("%-24s %7.3f %7.3f %7.3f %9.3f  %s\n", item.name.c_str(), item.width, item.depth, item.height,
					item.elevation, item.model.c_str());
			return 0;
		}
		if (args.has("--print-default-config"))
		{
			const std::string text = config::toIniText(CVisualSimulator::TOptions(), CVisualSimulator::TOptions::kSection);
			config::NumericKeyRecorder numbers;  // the ranges the readers check
			// The defaults with a generated home: a scenario needs a world.
			CVisualSimulator::TOptions().loadFromConfigFile(
				mrpt::config::CConfigFileMemory("[vslam_simul]\nworld_seed = 1\n"), CVisualSimulator::TOptions::kSection);
			std::cout << (args.has("--markdown") ? config::markdownReference(text, numbers.keys()) : text);
			return 0;
		}
		const auto& positional = args.positional;
		const auto& overrides = args.overrides;
		const bool quiet = args.has("--quiet");
		if (positional.size() != 2) throw std::invalid_argument("expected CONFIG.ini OUTPUT.rawlog");
		const std::string& ini = positional[0];
		const std::string text = config::readIniFile(ini);
		CVisualSimulator::TOptions options;
		try
		{
			options = loadVisualSimOptions(text, overrides, std::filesystem::path(ini).parent_path().string());
		}
		catch (const ConfigError& e)
		{
			throw ConfigError("'" + ini + "': " + e.what());
		}
		const SimulatedWorld world = loadSimulatedWorld(options);
		const world::FloorPlan& plan = world.plan;
		const CVisualSimulator simulator(options, plan);

		const std::string& rawlog = positional[1];
		mrpt::system::CTicTac clock;
		int lastPercent = -1;
		const VisualSimRun run = simulator.run(CRawlogReader::imagesDirectory(rawlog), [&](double f) {
			const int percent = static_cast<int>(f * 100);
			if (!quiet && percent / 10 != lastPercent / 10)
				std::cout << "vslam-simul: " << percent << "%\n" << std::flush;
			lastPercent = percent;
		});
		writeActionFrameRawlog(rawlog, run.entries);
		writeTumTrajectory(siblingFile(rawlog, "_groundtruth.tum"), run.truePath);
		writeTumTrajectory(siblingFile(rawlog, "_odometry.tum"), run.odometryPath);
		writeSimulationPreview(plan, run, siblingFile(rawlog, "_preview.png"));
		if (!world.generatedText.empty())
		{
			// The generated home as a world file: to read, edit, or give vslam-eval --world.
			const std::string file = siblingFile(rawlog, "_world.world");
			std::ofstream out(file);
			out << world.generatedText;
			out.close();
			if (!out) throw std::runtime_error("cannot write '" + file + "'");
		}
		const double wall = clock.Tac();
		std::cout << "vslam-simul: " << run.entries.size() << " steps (" << run.entries.size() * options.dt << " s simulated), "
				  << run.images << " images (" << run.blackFrames << " black), " << run.kidnapSteps.size()
				  << " kidnaps, " << run.slips << " slips; " << wall << " s wall, "
				  << (run.images > 0 ? run.images / std::max(run.renderSeconds, 1e-9) : 0.0)
				  << " rendered images/s -> " << rawlog << "\n";
		return 0;
	});
}

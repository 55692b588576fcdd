/** vslam-simul-measurements: a measurement-level rawlog with ground truth.
 *
 *   vslam-simul-measurements CONFIG.ini OUTPUT.rawlog [--set vslam_sim.KEY=VALUE ...]
 *
 * Reads [vslam_sim] (see config_ini/simul_measurements_example.ini) and
 * writes OUTPUT.rawlog, OUTPUT_groundtruth.tum and OUTPUT_landmarks.txt. */
#include <libvslam/app/ToolMain.h>
#include <libvslam/config/ConfigError.h>
#include <libvslam/config/KeyValidation.h>
#include <libvslam/config/Overrides.h>
#include <libvslam/core/InputError.h>
#include <libvslam/sim/SimulatedRunFiles.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <fstream>
#include <iostream>
#include <sstream>

namespace
{
const char* kUsage =
	"Usage: vslam-simul-measurements CONFIG.ini OUTPUT.rawlog [--set vslam_sim.KEY=VALUE ...]\n"
	"       vslam-simul-measurements --print-default-config\n";
}

int main(int argc, const char** argv)
{
	using namespace vslam;
	return vslam::runTool("vslam-simul-measurements", kUsage, [&]() -> int {
		std::vector<std::string> positional;
		std::vector<config::Override> overrides;
		for (int i = 1; i < argc; i++)
		{
			const std::string a = argv[i];
			if (a == "--help" || a == "-h")
			{
				std::cout << kUsage;
				return 0;
			}
			if (a == "--print-default-config")
			{
				mrpt::config::CConfigFileMemory c;
				TMeasurementSimOptions().saveToConfigFile(c, TMeasurementSimOptions::kSection);
				std::string text;
				c.getContent(text);
				std::cout << text;
				return 0;
			}
			if (a == "--set" && i + 1 < argc)
				overrides.push_back(config::parseOverride(argv[++i]));
			else if (a.rfind("--", 0) == 0)
				throw std::invalid_argument("unknown option '" + a + "'");
			else
				positional.push_back(a);
		}
		if (positional.size() != 2) throw std::invalid_argument("expected CONFIG.ini OUTPUT.rawlog");
		std::ifstream in(positional[0]);
		if (!in) throw ConfigError("cannot read configuration file '" + positional[0] + "'");
		std::stringstream text;
		text << in.rdbuf();
		TMeasurementSimOptions options;
		try
		{
			options = loadMeasurementSimOptions(text.str(), overrides);
		}
		catch (const ConfigError& e)
		{
			throw ConfigError("'" + positional[0] + "': " + e.what());
		}

		const SimulatedRun run = CMeasurementSimulator(options).run();
		const std::string& rawlog = positional[1];
		writeSimulatedRawlog(run, rawlog);
		writeSimulatedGroundTruth(run, siblingFile(rawlog, "_groundtruth.tum"));
		writeSimulatedLandmarks(run, siblingFile(rawlog, "_landmarks.txt"));
		std::cout << "vslam-simul-measurements: " << run.steps.size() << " steps, "
				  << run.creations << " landmark creations, " << run.visualMeasurements
				  << " visual measurements (" << run.badMeasurements << " bad, "
				  << run.falseRecognitions << " false recognitions), "
				  << run.rangeBearingMeasurements << " range-bearing measurements -> "
				  << rawlog << "\n";
		return 0;
	});
}

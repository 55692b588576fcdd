/** vslam-simul-measurements: a measurement-level rawlog with ground truth.
 *
 *   vslam-simul-measurements CONFIG.ini OUTPUT.rawlog [--set vslam_sim.KEY=VALUE ...]
 *
 * Reads [vslam_sim] (see config_ini/simul_measurements_example.ini) and
 * writes OUTPUT.rawlog, OUTPUT_groundtruth.tum and OUTPUT_landmarks.txt. */
#include <libvslam/app/ToolArguments.h>
#include <libvslam/app/ToolMain.h>
#include <libvslam/config/ConfigReference.h>
#include <libvslam/config/StrictRead.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <libvslam/config/ConfigError.h>
#include <libvslam/config/IniText.h>
#include <libvslam/config/KeyValidation.h>
#include <libvslam/config/Overrides.h>
#include <libvslam/core/InputError.h>
#include <libvslam/sim/SimulatedRunFiles.h>

#include <iostream>

namespace
{
const char* kUsage =
	"Usage: vslam-simul-measurements CONFIG.ini OUTPUT.rawlog [--set vslam_sim.KEY=VALUE ...]\n"
	"       vslam-simul-measurements --print-default-config [--markdown]\n";
}

int main(int argc, const char** argv)
{
	using namespace vslam;
	return vslam::runTool("vslam-simul-measurements", kUsage, [&]() -> int {
		const ToolArguments args = parseToolArguments(argc, argv, {}, {"--help", "--print-default-config", "--markdown"});
		if (args.has("--help"))
		{
			std::cout << kUsage;
			return 0;
		}
		if (args.has("--print-default-config"))
		{
			const std::string text = config::toIniText(CMeasurementSimulator::TOptions(), CMeasurementSimulator::TOptions::kSection);
			config::NumericKeyRecorder numbers;  // the ranges the readers check
			CMeasurementSimulator::TOptions().loadFromConfigFile(mrpt::config::CConfigFileMemory(), CMeasurementSimulator::TOptions::kSection);
			std::cout << (args.has("--markdown") ? config::markdownReference(text, numbers.keys()) : text);
			return 0;
		}
		const auto& positional = args.positional;
		if (positional.size() != 2) throw std::invalid_argument("expected CONFIG.ini OUTPUT.rawlog");
		const std::string text = config::readIniFile(positional[0]);
		CMeasurementSimulator::TOptions options;
		try
		{
			options = loadMeasurementSimOptions(text, args.overrides);
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

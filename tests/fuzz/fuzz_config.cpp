/** Fuzz target: INI options loading with --set overrides, for the vslam app
 * and the simulator. Input: override lines, a line "%%%%", then the INI
 * text. Any outcome but loaded options or a ConfigError / usage error
 * (std::invalid_argument) is a finding. */
#include <libvslam/app/CVSlamApp.h>
#include <libvslam/config/ConfigError.h>
#include <libvslam/config/Overrides.h>
#include <libvslam/sim/CMeasurementSimulator.h>
#include <tests/fuzz/FuzzInput.h>

#include <sstream>
#include <stdexcept>

namespace
{
std::vector<std::string> lines(const std::string& text)
{
	std::vector<std::string> out;
	std::istringstream in(text);
	for (std::string l; std::getline(in, l);) out.push_back(l);
	return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	const auto parts = vslam::fuzz::splitAtLines(data, size, "%%%%");
	const std::vector<std::string> overrides =
		parts.size() > 1 ? lines(parts[0]) : std::vector<std::string>{};
	const std::string& ini = parts.size() > 1 ? parts[1] : parts[0];
	static const std::string file = vslam::fuzz::scratchPath("config.ini");
	std::ofstream(file, std::ios::trunc) << ini;

	std::vector<std::string> args = {"vslam", file, "/nonexistent.rawlog", "--quiet"};
	for (const auto& o : overrides) args.insert(args.end(), {"--set", o});
	std::vector<const char*> argv;
	for (const auto& a : args) argv.push_back(a.c_str());
	try
	{
		vslam::CVSlamApp app;
		app.initialize(static_cast<int>(argv.size()), argv.data());
	}
	catch (const vslam::ConfigError&)
	{
	}
	catch (const std::invalid_argument&)
	{
	}
	try
	{
		std::vector<vslam::config::Override> parsed;
		for (const auto& o : overrides) parsed.push_back(vslam::config::parseOverride(o));
		vslam::loadMeasurementSimOptions(ini, parsed);
	}
	catch (const vslam::ConfigError&)
	{
	}
	return 0;
}

/** vslam-posed-images: the visual front-end on real photographs with exact
 * camera poses (Strecha layout: images/ + cameras/). Builds a landmark from
 * every run of consecutive views (true baseline plus odometry-like noise),
 * tries to recognize it from every other view and prints the accuracy of
 * the measured relative poses against the ground truth.
 *
 *   vslam-posed-images FOLDER [--config INI] [--set SECTION.KEY=VALUE ...]
 *                      [--seed N] [--odometry-noise REL DEG] [--csv FILE]
 *
 * --odometry-noise: std of the relative translation error and of the heading
 * error (deg) added to each increment between creation views (0.02 1).
 */
#include <libvslam/app/ToolMain.h>
#include <libvslam/config/ConfigError.h>
#include <libvslam/config/Overrides.h>
#include <libvslam/core/InputError.h>
#include <libvslam/tools/PosedImageEvaluation.h>

#include <filesystem>
#include <fstream>
#include <iostream>

namespace
{
const char* kUsage =
	"Usage: vslam-posed-images FOLDER [--config INI] [--set SECTION.KEY=VALUE ...]\n"
	"                          [--seed N] [--odometry-noise REL DEG] [--csv FILE]\n";
}

int main(int argc, const char** argv)
{
	using namespace vslam;
	return vslam::runTool("vslam-posed-images", kUsage, [&]() -> int {
		std::vector<std::string> positional;
		std::vector<config::Override> overrides;
		std::string iniFile, csvFile;
		TPosedImageEvaluationOptions options;
		for (int i = 1; i < argc; i++)
		{
			const std::string a = argv[i];
			const auto value = [&]() {
				if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
				return std::string(argv[++i]);
			};
			if (a == "--help" || a == "-h")
			{
				std::cout << kUsage;
				return 0;
			}
			if (a == "--set")
				overrides.push_back(config::parseOverride(value()));
			else if (a == "--config")
				iniFile = value();
			else if (a == "--csv")
				csvFile = value();
			else if (a == "--odometry-noise")
			{
				options.odometryTranslationNoise = std::stod(value());
				options.odometryHeadingNoiseDeg = std::stod(value());
			}
			else if (a == "--seed")
				options.seed = static_cast<uint32_t>(std::stoul(value()));
			else if (a.rfind("--", 0) == 0)
				throw std::invalid_argument("unknown option '" + a + "'");
			else
				positional.push_back(a);
		}
		if (positional.size() != 1) throw std::invalid_argument("expected one FOLDER");
		const CVisualFrontEnd::TOptions frontEnd = loadFrontEndOptions(iniFile, overrides);
		const auto views = readStrechaDataset(positional[0]);
		const auto result = evaluatePosedImages(views, frontEnd, options);
		const std::string title = std::filesystem::path(positional[0]).lexically_normal().filename().string();
		std::cout << formatPosedImageEvaluation(title.empty() ? positional[0] : title, result);
		if (!csvFile.empty())
		{
			std::ofstream csv(csvFile);
			csv << "landmark_view,query_view,recognized,distance,viewpoint_change_deg,heading_error_deg,"
				   "translation_error,NPoints,ProjErrRMS,Slope\n";
			for (const auto& r : result.records)
				csv << r.landmarkView << "," << r.queryView << "," << r.recognized << "," << r.distance << ","
					<< r.viewpointChangeDeg << "," << r.headingErrorDeg << "," << r.translationError << ","
					<< r.NPoints << "," << r.ProjErrRMS << "," << r.Slope << "\n";
		}
		return 0;
	});
}

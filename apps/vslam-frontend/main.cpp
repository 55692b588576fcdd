/** vslam-frontend: the visual front-end alone. Reads a rawlog with camera
 * images (CObservationImage, either rawlog format), runs the front-end
 * with the odometry of the same rawlog, and writes an actions/sensory-frames
 * rawlog in which every image is replaced by the landmark observations made
 * of it (CObservationVisualLandmark, CObservationLandmarkCreated); other
 * observations are kept. The output can be inspected with rawlog-edit
 * (LD_PRELOAD=libvslam_obs.so) and fed to vslam, so the front-end and the
 * filter can be tested and timed separately.
 *
 *   vslam-frontend IN.rawlog OUT.rawlog [--config INI] [--set vslam_frontend.KEY=VALUE ...]
 */
#include <libvslam/app/ToolMain.h>
#include <libvslam/config/ConfigError.h>
#include <libvslam/config/IniText.h>
#include <libvslam/config/Overrides.h>
#include <libvslam/core/ActionOdometry.h>
#include <libvslam/core/InputError.h>
#include <libvslam/frontend/ImagesToMeasurements.h>
#include <libvslam/io/CRawlogReader.h>
#include <libvslam/io/RawlogWriting.h>
#include <libvslam/obs/registerClasses.h>

#include <chrono>
#include <iostream>

namespace
{
const char* kUsage =
	"Usage: vslam-frontend IN.rawlog OUT.rawlog [--config INI] [--set vslam_frontend.KEY=VALUE ...]\n"
	"       vslam-frontend --print-default-config\n";
}

int main(int argc, const char** argv)
{
	using namespace vslam;
	registerObservationClasses();
	return vslam::runTool("vslam-frontend", kUsage, [&]() -> int {
		std::vector<std::string> positional;
		std::vector<config::Override> overrides;
		std::string iniFile;
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
				std::cout << config::toIniText(TVisualFrontEndOptions(), TVisualFrontEndOptions::kSection);
				return 0;
			}
			if ((a == "--set" || a == "--config") && i + 1 >= argc)
				throw std::invalid_argument(a + " needs a value");
			if (a == "--set")
				overrides.push_back(config::parseOverride(argv[++i]));
			else if (a == "--config")
				iniFile = argv[++i];
			else if (a.rfind("--", 0) == 0)
				throw std::invalid_argument("unknown option '" + a + "'");
			else
				positional.push_back(a);
		}
		if (positional.size() != 2) throw std::invalid_argument("expected IN.rawlog OUT.rawlog");
		const TVisualFrontEndOptions options = loadFrontEndOptions(iniFile, overrides);

		const auto start = std::chrono::steady_clock::now();
		CRawlogReader reader(positional[0]);
		CVisualFrontEnd frontEnd(options);
		std::vector<ActionFramePair> steps;
		mrpt::poses::CPose2D odometry;
		ImagesToMeasurementsResult total;
		RawlogStep step;
		while (reader.next(step))
		{
			if (step.action)
				if (const auto u = odometryIncrement(*step.action)) odometry = odometry + *u;
			const auto r = replaceImagesWithMeasurements(frontEnd, *step.sf, odometry,
				"rawlog '" + positional[0] + "', entry " + std::to_string(step.entry));
			total.images += r.images;
			total.measurements += r.measurements;
			total.created += r.created;
			total.pruned += r.pruned;
			auto action = step.action ? step.action : mrpt::obs::CActionCollection::Create();
			steps.emplace_back(action, step.sf);
		}
		writeActionFrameRawlog(positional[1], steps);
		const double seconds =
			std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
		const auto& t = frontEnd.totalSeconds();
		const auto& db = frontEnd.database();
		const auto perImage = [&](double s) { return total.images ? 1000 * s / total.images : 0.0; };
		std::cout << "vslam-frontend: " << total.images << " images -> " << total.measurements
				  << " landmark measurements, " << total.created << " landmarks created, " << total.pruned
				  << " pruned; " << db.size() << " in the database ("
				  << (db.size() ? db.landmarkBytes() / db.size() : 0) << " bytes each, index "
				  << db.indexBytes() << " bytes)\n"
				  << "vslam-frontend: ms per image: features " << perImage(t.features) << ", search "
				  << perImage(t.search) << ", pose " << perImage(t.pose) << ", creation "
				  << perImage(t.creation) << "; total " << seconds << " s -> " << positional[1] << "\n";
		return 0;
	});
}

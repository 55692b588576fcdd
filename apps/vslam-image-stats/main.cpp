/** vslam-image-stats: is an image rawlog good for the visual front-end?
 *
 *   vslam-image-stats RAWLOG TRUE_PATH [--config INI] [--set SECTION.KEY=VALUE ...]
 *
 * Prints SIFT features per image (the front-end's settings), and matches
 * (ratio test, then RANSAC fundamental-matrix inliers) between images 1 s
 * apart and at revisits (images 30 s or more apart taken within 0.3 m and
 * 15 deg of each other, by the true path TRUE_PATH). */
#include <libvslam/app/ToolArguments.h>
#include <libvslam/app/ToolMain.h>
#include <libvslam/config/Overrides.h>
#include <libvslam/obs/registerClasses.h>
#include <libvslam/frontend/CVisualFrontEnd.h>
#include <libvslam/tools/ImageSequenceStats.h>

#include <cstdio>
#include <iostream>

namespace
{
const char* kUsage =
	"Usage: vslam-image-stats RAWLOG TRUE_PATH [--config INI] [--set SECTION.KEY=VALUE ...]\n";
}

int main(int argc, const char** argv)
{
	using namespace vslam;
	registerObservationClasses();
	return vslam::runTool("vslam-image-stats", kUsage, [&]() -> int {
		const ToolArguments args = parseToolArguments(argc, argv, {"--config"}, {"--help"});
		if (args.has("--help"))
		{
			std::cout << kUsage;
			return 0;
		}
		const auto& positional = args.positional;
		if (positional.size() != 2) throw std::invalid_argument("expected RAWLOG TRUE_PATH");
		const auto options = loadFrontEndOptions(args.value("--config"), args.overrides);
		const auto s =
			computeImageSequenceStats(positional[0], readTrajectory(positional[1]), options.features, options.camera);
		std::printf("vslam-image-stats: %zu images; SIFT features per image: median %.0f, min %.0f, %zu images (%.0f%%) under 80\n",
			s.images, s.medianFeatures, s.minFeatures, s.imagesUnder80Features,
			s.images ? 100.0 * s.imagesUnder80Features / s.images : 0.0);
		const auto row = [](const char* what, const MatchStats& m) {
			std::printf("vslam-image-stats: %-12s %5zu pairs, median %4.0f matches, median %4.0f inliers, %zu pairs under 20 inliers\n",
				what, m.pairs, m.medianMatches, m.medianInliers, m.pairsWithUnder20Inliers);
		};
		row("1 s apart", s.apart);
		row("revisits", s.revisits);
		return 0;
	});
}

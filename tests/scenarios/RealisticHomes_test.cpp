/** The generated homes look to the front-end like real homes do, not like
 * wallpaper catalogues: on a minute of roaming through each of development
 * homes 1-3 with the shipped home camera (config_ini/simul_home.ini), the SIFT features
 * per 320x240 frame have a median of 120-280 and at least a tenth of the
 * frames have fewer than 80 (close to plain walls, along a hallway), as in
 * the realistic apartment the homes were modelled on (median 150-195, a
 * tenth under 60). Skipped without the texture packages. */
#include <gtest/gtest.h>
#include <libvslam/config/IniText.h>
#include <libvslam/tools/ImageSequenceStats.h>
#include <libvslam/frontend/ImageFeatures.h>
#include <libvslam/io/CRawlogReader.h>
#include <libvslam/io/RawlogWriting.h>
#include <libvslam/sim/CVisualSimulator.h>
#include <libvslam/sim/SimulatedWorld.h>
#include <tests/support/TempDir.h>

#include <algorithm>
#include <filesystem>

using namespace vslam;

TEST(RealisticHomes, FeaturesPerFrameAreThoseOfARealHome)
{
	if (!std::filesystem::is_directory("/usr/share/sweethome3d/furniture"))
		GTEST_SKIP() << "sweethome3d-furniture is not installed (scripts/setup.sh installs it)";
	const std::string ini = std::string(VSLAM_SOURCE_DIR) + "/config_ini/simul_home.ini";
	std::vector<double> features;
	for (const char* home : {"1", "2", "3"})
	{
		SCOPED_TRACE(std::string("home ") + home);
		CVisualSimulator::TOptions o = loadVisualSimOptions(config::readIniFile(ini),
			{config::parseOverride(std::string("vslam_simul.world_seed=") + home), config::parseOverride("vslam_simul.duration=60"),
				config::parseOverride("vslam_simul.laps=0"), config::parseOverride("vslam_simul.path_type=roam")},
			std::filesystem::path(ini).parent_path().string());
		const SimulatedWorld world = loadSimulatedWorld(o);
		vslam::testing::TempDir dir;
		const std::string rawlog = (dir.path() / "home.rawlog").string();
		const VisualSimRun run = CVisualSimulator(o, world.plan).run(CRawlogReader::imagesDirectory(rawlog));
		writeActionFrameRawlog(rawlog, run.entries);
		const auto stats = computeImageSequenceStats(rawlog, run.truePath, CFeatureExtractor::TOptions(), CImageCalibration::TOptions());
		features.insert(features.end(), stats.featureCounts.begin(), stats.featureCounts.end());
	}
	std::sort(features.begin(), features.end());
	const double median = features[features.size() / 2];
	const double under80 = double(std::lower_bound(features.begin(), features.end(), 80.0) - features.begin()) / features.size();
	std::printf("homes 1-3: %zu frames, SIFT features per frame median %.0f, %.0f%% under 80\n", features.size(), median,
		100 * under80);
	EXPECT_GE(median, 120);
	EXPECT_LE(median, 280);
	EXPECT_GE(under80, 0.10);
}

/** The INI files shipped in config_ini/ against the code's own options:
 * the example lists every key with its default, and every ready INI loads. */
#include <gtest/gtest.h>
#include <libvslam/app/CVSlamApp.h>
#include <libvslam/config/IniText.h>
#include <libvslam/config/KeyValidation.h>
#include <libvslam/config/Overrides.h>
#include <libvslam/frontend/CVisualFrontEnd.h>
#include <libvslam/models/CMotionModel.h>
#include <libvslam/sim/CVisualSimulator.h>
#include <libvslam/sim/CMeasurementSimulator.h>
#include <libvslam/sim/SimulatedWorld.h>
#include <libvslam/world/FloorPlanFile.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

using namespace vslam;
namespace fs = std::filesystem;

namespace
{
const fs::path kConfigDir = fs::path(VSLAM_SOURCE_DIR) / "config_ini";

mrpt::config::CConfigFileMemory readIni(const fs::path& file)
{
	std::ifstream in(file);
	EXPECT_TRUE(in.good()) << file;
	std::stringstream text;
	text << in.rdbuf();
	return mrpt::config::CConfigFileMemory(text.str());
}

std::string lower(std::string s)
{
	for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
	return s;
}

/** The effective options of the app for an INI, as INI text. */
std::string effectiveOptions(const fs::path& ini)
{
	CVSlamApp app;
	const std::string file = ini.string();
	const char* argv[] = {"vslam", file.c_str(), "unused.rawlog"};
	EXPECT_TRUE(app.initialize(3, argv));
	mrpt::config::CConfigFileMemory c;
	app.appOptions.saveToConfigFile(c, CVSlamApp::TOptions::kSection);
	app.filterOptions.saveToConfig(c);
	std::string text;
	c.getContent(text);
	return text;
}
}  // namespace

TEST(ConfigFiles, TheExampleListsEveryKeyOfEverySection)
{
	const auto ini = readIni(kConfigDir / "vslam_example.ini");
	const config::KnownKeys known = CVSlamApp::knownKeys();
	std::vector<std::string> iniSections;
	ini.getAllSections(iniSections);
	for (const auto& section : known.sections())
	{
		for (const auto& key : known.keys(section))
			EXPECT_TRUE(ini.keyExists(section, key))
				<< "[" << section << "] " << key << " is not in vslam_example.ini";
		EXPECT_NE(std::find_if(iniSections.begin(), iniSections.end(),
					  [&](const std::string& s) { return lower(s) == lower(section); }),
			iniSections.end())
			<< section;
	}
	// No stale keys either.
	EXPECT_NO_THROW(config::checkNoUnknownKeys(ini, known));
}

namespace
{
/** Every key of vslam with its default, as the effective configuration is written. */
std::string defaultOptionsText()
{
	mrpt::config::CConfigFileMemory defaults;
	CVSlamApp::TOptions().saveToConfigFile(defaults, CVSlamApp::TOptions::kSection);
	CVSlamParticleFilter::TOptions().saveToConfig(defaults);
	std::string text;
	defaults.getContent(text);
	return text;
}
}  // namespace

TEST(ConfigFiles, TheExampleShowsTheDefaults)
{
	EXPECT_EQ(effectiveOptions(kConfigDir / "vslam_example.ini"), defaultOptionsText());
}

namespace
{
/** Every key of `reference` has the same value in `actual`, but the
 * [vslam] keys in `vslamKeysThatMayDiffer` (lower case). */
void expectSameValues(const mrpt::config::CConfigFileMemory& reference, const mrpt::config::CConfigFileMemory& actual,
	const std::set<std::string>& vslamKeysThatMayDiffer)
{
	std::vector<std::string> sections;
	reference.getAllSections(sections);
	ASSERT_GT(sections.size(), 10u);
	for (const auto& section : sections)
	{
		std::vector<std::string> keys;
		reference.getAllKeys(section, keys);
		for (const auto& key : keys)
		{
			if (lower(section) == CVSlamApp::TOptions::kSection && vslamKeysThatMayDiffer.count(lower(key))) continue;
			EXPECT_EQ(actual.read_string(section, key, "<absent>"), reference.read_string(section, key, "<absent>"))
				<< "[" << section << "] " << key;
		}
	}
}
}  // namespace

TEST(ConfigFiles, TheCodesDefaultsAreTheCameraConfiguration)
{
	// camera.ini only names its input and output besides the defaults.
	expectSameValues(mrpt::config::CConfigFileMemory(defaultOptionsText()),
		mrpt::config::CConfigFileMemory(effectiveOptions(kConfigDir / "camera.ini")), {"rawlog_file", "output_dir"});
}

TEST(ConfigFiles, TheDemoIsTheCameraConfigurationWithTheDemosFiles)
{
	// Only these [vslam] keys may differ: the demo's data, output and seed.
	expectSameValues(mrpt::config::CConfigFileMemory(effectiveOptions(kConfigDir / "camera.ini")),
		mrpt::config::CConfigFileMemory(effectiveOptions(kConfigDir / "demo_rendered.ini")),
		{"rawlog_file", "output_dir", "random_seed", "ground_truth_file", "initial_pose_from_ground_truth"});
}

TEST(ConfigFiles, EveryShippedVslamIniLoads)
{
	size_t checked = 0;
	for (const auto& e : fs::directory_iterator(kConfigDir))
	{
		const auto name = e.path().filename().string();
		if (e.path().extension() != ".ini" || name.rfind("simul_", 0) == 0 || name.rfind("frontend_", 0) == 0)
			continue;
		SCOPED_TRACE(name);
		EXPECT_NO_THROW(effectiveOptions(e.path()));
		checked++;
	}
	EXPECT_GE(checked, 4u);
}

TEST(ConfigFiles, SimulatorIniFilesListKnownKeysOnly)
{
	config::KnownKeys known;
	known.addFromOptions(CMeasurementSimulator::TOptions(), CMeasurementSimulator::TOptions::kSection);
	const auto example = readIni(kConfigDir / "simul_measurements_example.ini");
	for (const auto& key : known.keys(CMeasurementSimulator::TOptions::kSection))
		EXPECT_TRUE(example.keyExists(CMeasurementSimulator::TOptions::kSection, key)) << key;
	for (const auto& e : fs::directory_iterator(kConfigDir))
	{
		if (e.path().filename().string().rfind("simul_", 0) != 0) continue;
		SCOPED_TRACE(e.path().filename().string());
		const auto ini = readIni(e.path());
		if (!ini.sectionExists(CMeasurementSimulator::TOptions::kSection)) continue;  // vslam-simul's
		EXPECT_NO_THROW(config::checkNoUnknownKeys(ini, known, CMeasurementSimulator::TOptions::kSection));
		CMeasurementSimulator::TOptions o;
		EXPECT_NO_THROW(o.loadFromConfigFile(ini, CMeasurementSimulator::TOptions::kSection));
	}
}

namespace
{
std::string frontEndIniText(const CVisualFrontEnd::TOptions& o)
{
	mrpt::config::CConfigFileMemory c;
	o.saveToConfig(c);
	std::string text;
	c.getContent(text);
	return text;
}
}  // namespace

TEST(ConfigFiles, FrontEndIniFilesListKnownKeysOnlyAndTheExampleShowsTheDefaults)
{
	config::KnownKeys known;
	CVisualFrontEnd::TOptions().registerKnownKeys(known);
	const auto example = readIni(kConfigDir / "frontend_example.ini");
	for (const auto& section : known.sections())
		for (const auto& key : known.keys(section)) EXPECT_TRUE(example.keyExists(section, key)) << section << " " << key;
	CVisualFrontEnd::TOptions fromExample;
	fromExample.loadFromConfig(example);
	EXPECT_EQ(frontEndIniText(fromExample), frontEndIniText(CVisualFrontEnd::TOptions()));
	size_t checked = 0;
	for (const auto& e : fs::directory_iterator(kConfigDir))
	{
		if (e.path().filename().string().rfind("frontend_", 0) != 0) continue;
		SCOPED_TRACE(e.path().filename().string());
		EXPECT_NO_THROW(loadFrontEndOptions(e.path().string(), {}));
		checked++;
	}
	EXPECT_GE(checked, 2u);
}

TEST(ConfigFiles, AKeyOfTheFormerFrontEndSectionSaysWhereItWent)
{
	try
	{
		loadFrontEndOptions("", {config::parseOverride("vslam_frontend.creation_views=4")});
		FAIL() << "expected ConfigError";
	}
	catch (const ConfigError& e)
	{
		EXPECT_NE(std::string(e.what()).find("is now [vslam_landmark_creation] views"), std::string::npos) << e.what();
	}
	// vslam itself, from an INI written for an earlier version.
	const fs::path dir = fs::temp_directory_path() / "vslam_moved_key_test";
	fs::create_directories(dir);
	const std::string ini = (dir / "old.ini").string();
	std::ofstream(ini) << "[vslam_frontend]\nheading_change = true\n";
	CVSlamApp app;
	const char* argv[] = {"vslam", ini.c_str(), "unused.rawlog"};
	try
	{
		app.initialize(3, argv);
		FAIL() << "expected ConfigError";
	}
	catch (const ConfigError& e)
	{
		EXPECT_NE(std::string(e.what()).find("is now [vslam_heading_measurement] enabled"), std::string::npos)
			<< e.what();
	}
	fs::remove_all(dir);
}

TEST(ConfigFiles, RenderedSimulatorIniFilesLoadAndTheExampleShowsTheDefaults)
{
	const std::string section = CVisualSimulator::TOptions::kSection;
	config::KnownKeys known;
	known.addFromOptions(CVisualSimulator::TOptions(), section);
	const auto example = readIni(kConfigDir / "simul_example.ini");
	for (const auto& key : known.keys(section)) EXPECT_TRUE(example.keyExists(section, key)) << key;
	CVisualSimulator::TOptions fromExample;
	fromExample.loadFromConfigFile(example, section);
	fromExample.world_file.clear();  // the one key without a default
	EXPECT_EQ(config::toIniText(fromExample, section), config::toIniText(CVisualSimulator::TOptions(), section));
	size_t checked = 0;
	for (const auto& e : fs::directory_iterator(kConfigDir))
	{
		if (e.path().extension() != ".ini" || !readIni(e.path()).sectionExists(section)) continue;
		SCOPED_TRACE(e.path().filename().string());
		std::ifstream in(e.path());
		std::stringstream text;
		text << in.rdbuf();
		// The options load, and the world (its file, or the home generated
		// from world_seed) and the path or people in it are valid (textures
		// exist, waypoints are collision-free).
		CVisualSimulator::TOptions o;
		ASSERT_NO_THROW(o = loadVisualSimOptions(text.str(), {}, kConfigDir.string()));
		if (o.world_seed != 0 && !fs::is_directory("/usr/share/sweethome3d/furniture"))
		{
			std::printf("%s: not generated, sweethome3d-furniture is not installed\n", e.path().filename().c_str());
			continue;
		}
		const auto world = loadSimulatedWorld(o);
		EXPECT_NO_THROW(CVisualSimulator(o, world.plan));
		checked++;
	}
	EXPECT_GE(checked, 6u);
}

TEST(ConfigFiles, TheScaleTracksOdometryNoiseIsTheMotionModelsUnlessSet)
{
	const fs::path dir = fs::temp_directory_path() / "vslam_scale_sigma_test";
	fs::create_directories(dir);
	const fs::path ini = dir / "run.ini";
	std::ofstream(ini) << "[vslam_motion_model]\nsigma_T = 0.08\n";
	// Both apps that run the front-end: vslam and (via loadFrontEndOptions) vslam-frontend.
	CVSlamApp app;
	const std::string file = ini.string();
	const char* argv[] = {"vslam", file.c_str(), "unused.rawlog"};
	ASSERT_TRUE(app.initialize(3, argv));
	EXPECT_EQ(app.frontEndOptions.scale.odometry_sigma, 0.08);
	EXPECT_EQ(loadFrontEndOptions(file, {}).scale.odometry_sigma, 0.08);
	// Given explicitly, the front-end's own value stands.
	const auto own = loadFrontEndOptions(file, {config::parseOverride("vslam_scale_refinement.odometry_sigma=0.03")});
	EXPECT_EQ(own.scale.odometry_sigma, 0.03);
	EXPECT_EQ(loadFrontEndOptions("", {}).scale.odometry_sigma, CMotionModel::TOptions().sigma_T);
	fs::remove_all(dir);
}

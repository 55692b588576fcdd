/** Every numeric key of vslam at the edges of its allowed range and beyond:
 * the keys and their ranges come from the option structs themselves (the
 * NumericKeyRecorder), not from a list kept by hand. */
#include <gtest/gtest.h>
#include <libvslam/app/CVSlamApp.h>
#include <libvslam/config/StrictRead.h>
#include <libvslam/io/CRawlogReader.h>
#include <libvslam/io/RawlogWriting.h>
#include <libvslam/obs/registerClasses.h>
#include <tests/support/RunCommand.h>
#include <tests/support/TempDir.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <regex>
#include <sstream>

using namespace vslam;
using vslam::testing::readFile;
using vslam::testing::TempDir;
namespace fs = std::filesystem;

namespace
{
const bool kRegistered = (vslam::registerObservationClasses(), true);
const std::string kSource = VSLAM_SOURCE_DIR;

std::string text(double v)
{
	if (std::isnan(v)) return "nan";
	if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
	std::ostringstream o;
	o.precision(17);
	o << v;
	return o.str();
}

struct Case
{
	std::string value;
	bool allowed;
};

/** The range's ends, a step beyond each, and the non-finite values. */
std::vector<Case> casesFor(const config::NumericKey& k)
{
	std::vector<Case> cases = {{"nan", false}, {"inf", false}, {"-inf", false}};
	const auto beyond = [&](double end, double direction) {
		const double step = k.integer ? 1 : std::max(1e-6, std::abs(end) * 1e-3);
		return end + direction * step;
	};
	const config::Range& r = k.range;
	if (std::isfinite(r.lo))
	{
		if (r.loInclusive) cases.push_back({text(r.lo), true});
		cases.push_back({text(beyond(r.lo, -1)), false});
	}
	else
		cases.push_back({"-1e300", true});  // any number: the largest a user may write
	if (std::isfinite(r.hi))
	{
		if (r.hiInclusive) cases.push_back({text(r.hi), true});
		cases.push_back({text(beyond(r.hi, +1)), false});
	}
	else
		cases.push_back({"1e300", true});
	if (k.integer)
		for (auto& c : cases)
			if (c.value == "1e300" || c.value == "-1e300") c = {c.value, false};  // beyond any integer
	return cases;
}

/** vslam in this process; the exit code and what it printed. */
int runVslam(const std::vector<std::string>& args, std::string& messages)
{
	std::vector<const char*> argv = {"vslam"};
	for (const auto& a : args) argv.push_back(a.c_str());
	std::ostringstream captured;
	auto* old = std::cerr.rdbuf(captured.rdbuf());
	const int code = CVSlamApp().main(static_cast<int>(argv.size()), argv.data());
	std::cerr.rdbuf(old);
	messages = captured.str();
	return code;
}

/** The first \a steps steps of \a rawlog, written to \a file: each case
 * runs 20 steps, and the reader's whole-file check then reads no more. */
std::string headOf(const std::string& rawlog, size_t steps, const std::string& file)
{
	vslam::CRawlogReader reader(rawlog);
	std::vector<vslam::ActionFramePair> head;
	vslam::RawlogStep step;
	while (head.size() < steps && reader.next(step))
		head.emplace_back(step.action ? step.action : mrpt::obs::CActionCollection::Create(), step.sf);
	vslam::writeActionFrameRawlog(file, head);
	return file;
}

/** A NaN or infinity written anywhere in the output folder. */
std::string nonFiniteOutput(const std::string& dir)
{
	static const std::regex nonFinite(R"((^|[\s:,{\[])[-+]?(nan|inf)($|[\s,}\]]))", std::regex::icase);
	for (const auto& f : fs::directory_iterator(dir))
		if (std::regex_search(readFile(f.path().string()), nonFinite)) return f.path().filename().string();
	return "";
}
}  // namespace

TEST(ExtremeValues, EveryNumericKeyAtAndBeyondItsLimitsEndsAsDocumented)
{
	const std::string rawlogs[] = {kSource + "/rawlogs/demo_visual.rawlog", "/usr/share/mrpt/datasets/kf-slam_demo.rawlog"};
	const auto keys = CVSlamApp::numericKeys();
	ASSERT_GT(keys.size(), 60u);
	TempDir dir;
	size_t cases = 0, rejected = 0, ran = 0, stoppedNonFinite = 0;
	for (const auto& whole : rawlogs)
	{
		if (!fs::exists(whole)) continue;
		const std::string rawlog = headOf(whole, 25, dir.file(fs::path(whole).filename().string()));
		for (const auto& k : keys)
			for (const auto& c : casesFor(k))
			{
				const std::string out = dir.file("o" + std::to_string(cases++));
				const std::string key = k.section + "." + k.key;
				std::vector<std::string> args = {kSource + "/config_ini/demo_visual.ini", rawlog, "--out", out, "--quiet",
					"--set", "vslam.max_steps=20", "--set", "vslam.initial_pose_from_ground_truth=false", "--set",
					"vslam.ground_truth_file="};
				if (k.key != "sampleSize") args.insert(args.end(), {"--set", "vslam_particle_filter.sampleSize=20"});
				if (k.key == "sampleSize" && c.allowed) args.insert(args.end(), {"--set", "vslam.max_steps=2"});
				args.insert(args.end(), {"--set", key + "=" + c.value});
				if (std::getenv("VSLAM_TRACE_CASES")) std::cout << key << " = " << c.value << " " << rawlog << std::endl;
				std::string messages;
				const int code = runVslam(args, messages);
				const std::string what = key + " = " + c.value + " on " + fs::path(rawlog).filename().string();
				if (!c.allowed)
				{
					rejected++;
					EXPECT_EQ(code, CVSlamApp::kConfigError) << what << "\n" << messages;
					EXPECT_NE(messages.find("[" + k.section + "] " + k.key + " = '" + c.value + "'"), std::string::npos)
						<< what << "\n" << messages;
					EXPECT_FALSE(fs::exists(out)) << what << ": a configuration error writes nothing";
					continue;
				}
				if (code == CVSlamApp::kConfigError && messages.find(k.key) != std::string::npos &&
					messages.find(" must ") != std::string::npos)
				{
					rejected++;  // a rule between keys (e.g. min <= max), naming the key
					continue;
				}
				ran++;
				if (code == CVSlamApp::kOtherError && messages.find("no longer finite") != std::string::npos)
					stoppedNonFinite++;  // documented: the run stops naming the step and the keys
				else
					EXPECT_EQ(code, CVSlamApp::kOk) << what << "\n" << messages;
				if (fs::exists(out))
				{
					EXPECT_EQ(nonFiniteOutput(out), "") << what;
				}
				fs::remove_all(out);
			}
	}
	std::cout << "[ExtremeValues] " << keys.size() << " numeric keys, " << cases << " cases: " << rejected
			  << " rejected as configuration errors, " << ran << " ran (" << stoppedNonFinite
			  << " stopped on a non-finite filter state)\n";
}

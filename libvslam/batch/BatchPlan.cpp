#include <libvslam/app/CVSlamApp.h>
#include <libvslam/batch/BatchPlan.h>
#include <libvslam/config/ConfigError.h>
#include <libvslam/config/KeyValidation.h>
#include <libvslam/config/Overrides.h>
#include <libvslam/config/StrictRead.h>
#include <libvslam/core/AllottedCpus.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace vslam::batch
{
namespace
{
constexpr const char* kScenarioPrefix = "scenario:";

/** Whitespace-separated words, or with a separator the trimmed non-empty
 * items between separators. */
std::vector<std::string> words(const std::string& text, char separator = 0)
{
	std::vector<std::string> out;
	std::istringstream in(text);
	std::string item;
	if (!separator)
	{
		while (in >> item) out.push_back(item);
		return out;
	}
	while (std::getline(in, item, separator))
	{
		item.erase(0, item.find_first_not_of(" \t"));
		item.erase(item.find_last_not_of(" \t") + 1);
		if (!item.empty()) out.push_back(item);
	}
	return out;
}

/** "1 2 5" or "1-20" or a mix ("1-5 9"). */
std::vector<int> parseSeeds(const std::string& text, const std::string& where)
{
	std::vector<int> seeds;
	for (const auto& w : words(text))
	{
		const auto dash = w.find('-', 1);
		try
		{
			size_t used = 0;
			const int a = std::stoi(w.substr(0, dash), &used);
			if (used != (dash == std::string::npos ? w.size() : dash)) throw std::invalid_argument(w);
			int b = a;
			if (dash != std::string::npos)
			{
				b = std::stoi(w.substr(dash + 1), &used);
				if (used != w.size() - dash - 1) throw std::invalid_argument(w);
			}
			if (a < 0 || b < a || b - a > 100000) throw std::invalid_argument(w);
			for (int s = a; s <= b; s++) seeds.push_back(s);
		}
		catch (const std::exception&)
		{
			throw ConfigError(where + ": '" + w + "' is not a seed or a range of seeds (e.g. 1-20)");
		}
	}
	if (seeds.empty()) throw ConfigError(where + ": no seeds");
	std::sort(seeds.begin(), seeds.end());
	if (std::adjacent_find(seeds.begin(), seeds.end()) != seeds.end())
		throw ConfigError(where + ": a seed is given twice");
	return seeds;
}

/** The keys whose value is a path (relative to the batch file's folder). */
bool isPathKey(const std::string& key)
{
	static const std::set<std::string> paths{
		"output_dir", "vslam_ini", "simul_ini", "rawlog", "ground_truth", "world", "rbpf_slam_ini"};
	return paths.count(key) > 0;
}

/** A command-line override with its path, if it gives one, made absolute
 * against the current folder. */
config::Override withAbsolutePath(const std::string& text)
{
	config::Override o = config::parseOverride(text);
	if (o.section != "grid" && isPathKey(o.key) && !o.value.empty() && fs::path(o.value).is_relative())
		o.value = fs::absolute(o.value).lexically_normal().string();
	return o;
}

class BatchFile
{
   public:
	/** \a overrides: with absolute paths; a [grid] key without a value
	 * drops that axis. */
	BatchFile(const std::string& file, const std::vector<config::Override>& overrides) : m_file(file)
	{
		const std::string text = config::readIniFile(file);
		std::vector<std::string> fileSections;
		config::parseIniWithOverrides(text, {}).getAllSections(fileSections);
		std::vector<config::Override> applied;
		for (const auto& o : overrides)
		{
			const bool addable = o.section == "grid" || o.section == "slurm";  // optional sections
			if (!addable && std::find(fileSections.begin(), fileSections.end(), o.section) == fileSections.end())
				throw ConfigError("override '" + o.text() + "': batch '" + file + "' has no section [" + o.section + "]");
			if (o.section == "grid" && o.value.empty())
			{
				m_droppedGridKeys.insert(o.key);
				continue;
			}
			if (o.section == "grid") m_droppedGridKeys.erase(o.key);  // the later override wins
			applied.push_back(o);
		}
		m_cfg = config::parseIniWithOverrides(text, applied);
		for (const auto& key : m_droppedGridKeys)
			if (m_cfg.read_string("grid", key, "", false).empty())
				throw ConfigError("override 'grid." + key + "=': no such key in " + where("grid") +
					" to leave out");
	}

	std::string where(const std::string& section, const std::string& key = "") const
	{
		return "batch '" + m_file + "', [" + section + "]" + (key.empty() ? "" : " " + key);
	}

	/** Throws naming the first key of \a section not in \a allowed. */
	void onlyKeys(const std::string& section, const std::vector<std::string>& allowed) const
	{
		std::vector<std::string> keys;
		m_cfg.getAllKeys(section, keys);
		for (const auto& k : keys)
			if (std::find(allowed.begin(), allowed.end(), k) == allowed.end())
			{
				const std::string close = config::closestMatch(k, allowed);
				throw ConfigError(where(section, k) + ": unknown key" +
					(close.empty() ? "" : " (did you mean '" + close + "'?)"));
			}
	}

	std::string text(const std::string& section, const std::string& key) const
	{
		return m_cfg.read_string(section, key, "", false);
	}

	/** A whole number in [lo, hi] (read as every INI key is), or \a absent
	 * if the key is not there or empty. */
	int wholeNumber(const std::string& section, const std::string& key, int lo, int hi, int absent) const
	{
		if (text(section, key).empty()) return absent;
		try
		{
			return int(config::readInt(m_cfg, section, key, absent, config::Range::closed(lo, hi)));
		}
		catch (const ConfigError& e)
		{
			throw ConfigError("batch '" + m_file + "', " + e.what());
		}
	}

	/** A path relative to the batch file's folder, made absolute; must
	 * exist if asked. */
	std::string path(const std::string& section, const std::string& key, bool mustExist) const
	{
		const std::string value = text(section, key);
		if (value.empty()) return "";
		const fs::path p = fs::path(value).is_absolute() ? fs::path(value) : fs::path(m_file).parent_path() / value;
		if (mustExist && !fs::exists(p)) throw ConfigError(where(section, key) + ": no file '" + p.string() + "'");
		return fs::absolute(p).lexically_normal().string();  // the programs run elsewhere
	}

	std::vector<std::string> sections() const
	{
		std::vector<std::string> s;
		m_cfg.getAllSections(s);
		return s;
	}

	/** The keys of \a section, but the grid axes an override dropped. */
	std::vector<std::string> keys(const std::string& section) const
	{
		std::vector<std::string> k;
		m_cfg.getAllKeys(section, k);
		if (section == "grid")
			k.erase(std::remove_if(k.begin(), k.end(), [&](const std::string& key) { return m_droppedGridKeys.count(key) > 0; }),
				k.end());
		return k;
	}

   private:
	std::string m_file;
	mrpt::config::CConfigFileMemory m_cfg;
	std::set<std::string> m_droppedGridKeys;
};

/** The [slurm] section: what vslam-batch --slurm asks of the cluster. */
TSlurmOptions readSlurmSettings(const BatchFile& f)
{
	f.onlyKeys("slurm", {"cpus_per_task", "mem_mib", "time_minutes", "throttle", "max_array_size", "partition", "account",
							"sbatch_options"});
	TSlurmOptions s;
	s.cpusPerTask = f.wholeNumber("slurm", "cpus_per_task", 1, 1024, 1);
	s.memMiB = f.wholeNumber("slurm", "mem_mib", 0, 1 << 24, 0);
	s.timeMinutes = f.wholeNumber("slurm", "time_minutes", 0, 60 * 24 * 365, 0);
	s.throttle = f.wholeNumber("slurm", "throttle", 0, 1 << 20, 0);
	s.maxArraySize = f.wholeNumber("slurm", "max_array_size", 0, 1 << 22, 0);
	s.partition = f.text("slurm", "partition");
	s.account = f.text("slurm", "account");
	for (const auto& option : words(f.text("slurm", "sbatch_options"))) s.sbatchOptions.push_back(option);
	return s;
}

/** Loads the variation's vslam configuration exactly as vslam would: an
 * unknown key or a bad value is found before anything runs. */
void checkVslamConfig(const Scenario& s, const Variation& v, const std::string& where)
{
	std::vector<std::string> args{"vslam", s.vslamIni, "(rawlog)"};
	for (const auto& list : {s.vslamSet, v.set})
		for (const auto& kv : list) args.insert(args.end(), {"--set", kv});
	std::vector<const char*> argv;
	for (const auto& a : args) argv.push_back(a.c_str());
	try
	{
		CVSlamApp app;
		app.initialize(int(argv.size()), argv.data());
	}
	catch (const std::exception& e)
	{
		throw ConfigError(where + ": " + e.what());
	}
}

std::vector<Variation> expandGrid(const BatchFile& f)
{
	// Every combination of the grid's values, the first key varying slowest.
	std::vector<Variation> out{Variation{}};
	for (const auto& key : f.keys("grid"))
	{
		const auto values = words(f.text("grid", key));
		if (values.empty()) throw ConfigError(f.where("grid", key) + ": no values");
		std::vector<Variation> next;
		for (const auto& v : out)
			for (const auto& value : values)
			{
				Variation w = v;
				w.set.push_back(key + "=" + value);
				next.push_back(w);
			}
		out = next;
	}
	for (auto& v : out)
	{
		// FNV-1a of the settings: the same settings, the same folder.
		uint64_t hash = 14695981039346656037ull;
		for (const char c : v.label()) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
		char name[24];
		std::snprintf(name, sizeof name, "v%08x", static_cast<unsigned>(hash >> 32));
		v.name = v.set.empty() ? "defaults" : name;
	}
	return out;
}
}  // namespace

std::string Variation::label() const
{
	if (set.empty()) return "defaults";
	std::string s;
	for (const auto& kv : set) s += (s.empty() ? "" : ", ") + kv;
	return s;
}

std::string BatchPlan::rawlogOf(const Scenario& s, int seed) const
{
	if (s.simulIni.empty()) return s.rawlog;
	return (fs::path(outputDir) / s.name / ("data_seed" + std::to_string(seed)) / "sim.rawlog").string();
}

std::string BatchPlan::groundTruthOf(const Scenario& s, int seed) const
{
	if (s.simulIni.empty()) return s.groundTruth;
	return (fs::path(outputDir) / s.name / ("data_seed" + std::to_string(seed)) / "sim_groundtruth.tum").string();
}

std::string BatchPlan::worldOf(const Scenario& s, int seed) const
{
	if (s.simulIni.empty()) return s.world;
	const fs::path generated = fs::path(rawlogOf(s, seed)).parent_path() / "sim_world.world";
	return fs::exists(generated) ? generated.string() : s.world;
}

std::string BatchPlan::peerDirOf(const Scenario& s, int seed) const
{
	return (fs::path(outputDir) / s.name / "rbpf-slam" / ("seed" + std::to_string(seed))).string();
}

const Task* BatchPlan::find(const std::string& id) const
{
	for (const auto& t : tasks)
		if (t.id == id) return &t;
	return nullptr;
}

BatchPlan loadBatchPlan(const std::string& batchFile, const std::vector<std::string>& overrides)
{
	if (!fs::is_regular_file(batchFile)) throw ConfigError("no batch file '" + batchFile + "'");
	BatchPlan plan;
	plan.batchFile = batchFile;
	std::vector<config::Override> parsed;
	for (const auto& text : overrides)
	{
		parsed.push_back(withAbsolutePath(text));
		plan.overrides.push_back(parsed.back().text());
	}
	const BatchFile f(batchFile, parsed);
	for (const auto& section : f.sections())
		if (section != "batch" && section != "grid" && section != "slurm" && section.rfind(kScenarioPrefix, 0) != 0)
			throw ConfigError("batch '" + batchFile + "': unknown section [" + section +
				"] (expected [batch], [grid], [slurm] and [scenario:NAME] sections)");

	f.onlyKeys("batch", {"output_dir", "seeds", "jobs", "vslam_ini", "set", "rbpf_slam_ini"});
	plan.rbpfSlamIni = f.path("batch", "rbpf_slam_ini", true);
	plan.outputDir = f.path("batch", "output_dir", false);
	if (plan.outputDir.empty()) throw ConfigError(f.where("batch", "output_dir") + ": missing");
	plan.seeds = parseSeeds(f.text("batch", "seeds"), f.where("batch", "seeds"));
	plan.jobs = f.wholeNumber("batch", "jobs", 0, 1024, 0);
	if (plan.jobs == 0) plan.jobs = allottedCpus();  // within a cluster allocation: what it was given
	plan.slurm = readSlurmSettings(f);
	const std::string defaultVslamIni = f.path("batch", "vslam_ini", true);
	const auto batchSet = words(f.text("batch", "set"), ';');

	for (const auto& section : f.sections())
	{
		if (section.rfind(kScenarioPrefix, 0) != 0) continue;
		f.onlyKeys(section, {"simul_ini", "simul_set", "rawlog", "ground_truth", "vslam_ini", "set", "world"});
		Scenario s;
		s.name = section.substr(std::string(kScenarioPrefix).size());
		if (s.name.empty() || s.name.find_first_of("/ \t") != std::string::npos)
			throw ConfigError("batch '" + batchFile + "': [" + section + "] needs a name without '/' or spaces");
		s.simulIni = f.path(section, "simul_ini", true);
		s.simulSet = words(f.text(section, "simul_set"), ';');
		s.rawlog = f.path(section, "rawlog", true);
		s.groundTruth = f.path(section, "ground_truth", true);
		if (s.simulIni.empty() == s.rawlog.empty())
			throw ConfigError(f.where(section) + ": give either simul_ini or rawlog (with ground_truth)");
		if (!s.rawlog.empty() && s.groundTruth.empty())
			throw ConfigError(f.where(section, "ground_truth") + ": missing (the runs are scored against it)");
		s.vslamIni = f.path(section, "vslam_ini", true);
		if (s.vslamIni.empty()) s.vslamIni = defaultVslamIni;
		if (s.vslamIni.empty())
			throw ConfigError(f.where(section, "vslam_ini") + ": missing here and in [batch]");
		s.vslamSet = batchSet;
		for (const auto& kv : words(f.text(section, "set"), ';')) s.vslamSet.push_back(kv);
		s.world = f.path(section, "world", true);
		plan.scenarios.push_back(s);
	}
	if (plan.scenarios.empty()) throw ConfigError("batch '" + batchFile + "': no [scenario:NAME] section");
	plan.variations = expandGrid(f);
	for (const auto& s : plan.scenarios)
		for (const auto& v : plan.variations)
			checkVslamConfig(s, v, f.where("scenario:" + s.name) + ", variation " + v.label());

	for (size_t si = 0; si < plan.scenarios.size(); si++)
	{
		const Scenario& s = plan.scenarios[si];
		if (s.simulIni.empty()) continue;
		for (const int seed : plan.seeds)
			plan.tasks.push_back({Task::Kind::Render, si, 0, seed, "render/" + s.name + "/seed" + std::to_string(seed),
				fs::path(plan.rawlogOf(s, seed)).parent_path().string()});
	}
	for (size_t si = 0; si < plan.scenarios.size() && !plan.rbpfSlamIni.empty(); si++)
	{
		const Scenario& s = plan.scenarios[si];
		if (s.simulIni.empty()) continue;  // only rendered rawlogs surely carry laser scans
		for (const int seed : plan.seeds)
			plan.tasks.push_back({Task::Kind::Peer, si, 0, seed, "peer/" + s.name + "/seed" + std::to_string(seed),
				plan.peerDirOf(s, seed)});
	}
	for (size_t si = 0; si < plan.scenarios.size(); si++)
		for (size_t vi = 0; vi < plan.variations.size(); vi++)
			for (const int seed : plan.seeds)
			{
				const std::string tail =
					plan.scenarios[si].name + "/" + plan.variations[vi].name + "/seed" + std::to_string(seed);
				plan.tasks.push_back({Task::Kind::Run, si, vi, seed, "run/" + tail,
					(fs::path(plan.outputDir) / tail).string()});
			}
	return plan;
}
}  // namespace vslam::batch

#pragma once
/** \file BatchPlan.h
 * An experiment batch from one INI file (vslam-batch; doc/experiments.md):
 *
 *   [batch]
 *   output_dir = ../../batch_out/paper   ; paths relative to this file
 *   seeds = 1-20                         ; or a list: 1 2 3
 *   jobs = 0                             ; runs at a time; 0: one per CPU it may use
 *   vslam_ini = ../demo_rendered.ini     ; vslam's configuration
 *   set = vslam_particle_filter.sampleSize=200 ; ... for every run
 *   rbpf_slam_ini = ../peers/rbpf-slam_gridmapping.ini ; optional: MRPT's
 *                                        ; rbpf-slam (laser) on every rendered rawlog
 *
 *   [scenario:living_room]               ; one section per data source:
 *   simul_ini = ../simul_living_room.ini ; rendered per seed (vslam_simul.seed), or
 *   rawlog = ...  ground_truth = ...     ; fixed data (the seed varies vslam only)
 *   simul_set = vslam_simul.duration=300 ; simulator overrides ({seed}: the seed,
 *                                        ; e.g. vslam_simul.world_seed={seed}: a home per seed)
 *   vslam_ini = ...  set = ...           ; per-scenario vslam overrides
 *
 *   [grid]                               ; vslam keys, values separated by spaces:
 *   vslam_particle_filter.sampleSize = 100 200 400   ; every combination is a variation
 *                                        ; (keys in alphabetical order, the first varying slowest;
 *                                        ; each in a folder named by a hash of its settings)
 *
 *   [slurm]                              ; optional: vslam-batch --slurm (SlurmSubmission.h)
 *   cpus_per_task = 1   mem_mib = 0   time_minutes = 0   ; 0: from the finished tasks' needs
 *   throttle = 0   max_array_size = 0    ; array tasks at a time (0: no limit); 0: the cluster's
 *   partition =   account =   sbatch_options = --qos=low   ; passed to every sbatch
 *
 * The plan is the list of tasks: rendering each simulated scenario once per
 * seed, rbpf-slam on each rendered rawlog (if asked), then one vslam run
 * per scenario, variation and seed. */
#include <string>
#include <vector>

namespace vslam::batch
{
struct Scenario
{
	std::string name;
	std::string simulIni;  //!< rendered per seed, or empty
	std::vector<std::string> simulSet;
	std::string rawlog, groundTruth;  //!< fixed data (when no simulIni)
	std::string vslamIni;
	std::vector<std::string> vslamSet;  //!< the batch's `set`, then the scenario's
	std::string world;  //!< floor plan under the runs' figures (optional)
};

struct Variation
{
	/** Its folder: "defaults", or "v" + 8 hex digits of a hash of its
	 * settings, so that the folder stays when the grid grows or is reordered
	 * (finished runs are then kept, not redone). */
	std::string name;
	std::vector<std::string> set;  //!< SECTION.KEY=VALUE
	std::string label() const;  //!< "key=value, key=value" or "defaults"
};

struct Task
{
	enum class Kind
	{
		Render,
		Peer,  //!< MRPT's rbpf-slam on a rendered rawlog
		Run
	};
	Kind kind = Kind::Run;
	size_t scenario = 0;  //!< index in BatchPlan::scenarios
	size_t variation = 0;  //!< index in BatchPlan::variations (Run only)
	int seed = 0;
	std::string id;  //!< "render/living_room/seed3", "peer/living_room/seed3", "run/living_room/v5c1e09a7/seed3"
	std::string dir;  //!< its output folder
};

/** What the batch asks of a Slurm cluster ([slurm]); see SlurmSubmission.h. */
struct TSlurmOptions
{
	int cpusPerTask = 1;
	int memMiB = 0;  //!< per task; 0: measured (or a default when nothing is measured)
	int timeMinutes = 0;  //!< per task; 0: measured (or a default)
	int throttle = 0;  //!< array tasks running at a time (the %N of --array); 0: no limit
	int maxArraySize = 0;  //!< the cluster's MaxArraySize; 0: ask scontrol (1001 if it cannot tell)
	std::string partition, account;
	std::vector<std::string> sbatchOptions;
};

struct BatchPlan
{
	std::string batchFile, outputDir;
	/** The changes to the batch file's keys it was loaded with (SECTION.KEY=VALUE),
	 * their relative paths made absolute: a listed task carries them. */
	std::vector<std::string> overrides;
	std::vector<int> seeds;
	int jobs = 0;
	TSlurmOptions slurm;
	/** rbpf-slam's configuration (its peers' runs are scored beside vslam's), or empty. */
	std::string rbpfSlamIni;
	std::vector<Scenario> scenarios;
	std::vector<Variation> variations;
	std::vector<Task> tasks;  //!< every Render, then every Peer, then every Run

	/** The rawlog and ground truth a run of \a scenario with \a seed reads. */
	std::string rawlogOf(const Scenario& scenario, int seed) const;
	std::string groundTruthOf(const Scenario& scenario, int seed) const;
	/** The generated home a rendered run of \a scenario drove through, if any. */
	std::string worldOf(const Scenario& scenario, int seed) const;
	/** The folder of rbpf-slam's run on \a scenario with \a seed. */
	std::string peerDirOf(const Scenario& scenario, int seed) const;
	const Task* find(const std::string& id) const;
};

/** Reads and checks a batch file: unknown sections or keys, missing files,
 * bad seeds and every variation's vslam configuration (loaded as vslam
 * would) are ConfigErrors naming the file, section and key.
 *
 * \a overrides ("SECTION.KEY=VALUE", vslam-batch --set) change the file's
 * keys before it is read, so an experiment on a shipped batch needs no
 * copy of it: "grid.vslam_prefilter.max_Slope=0.02 0.1" adds or replaces a
 * grid axis, "grid.KEY=" (no value) removes one (it must be in the grid),
 * "batch.output_dir=DIR" moves the outputs. A relative path given this way
 * (output_dir, vslam_ini, simul_ini, rawlog, ground_truth, world) is
 * relative to the current folder, not to the batch file. The same checks
 * apply: a misspelt section or key is an error naming it. */
BatchPlan loadBatchPlan(const std::string& batchFile, const std::vector<std::string>& overrides = {});
}  // namespace vslam::batch

#pragma once
/** \file SlurmSubmission.h
 * A batch as Slurm job arrays (vslam-batch BATCH.ini --slurm DIR
 * [--submit]; doc/experiments.md). DIR receives:
 *  - tasks.txt: one self-contained command per task (ListedTasks.h);
 *  - task.sh: an array element, running line FIRST + SLURM_ARRAY_TASK_ID;
 *  - summary.sh: vslam-batch --summary;
 *  - submit.sh: the sbatch calls. The renderings' arrays go first; the
 *    runs' arrays wait for all of them to succeed (afterok), and a failed
 *    rendering cancels them (--kill-on-invalid-dep) rather than leaving
 *    them pending for ever; the summary waits for the runs to end, however
 *    they end (afterany). Arrays are cut into chunks whose indices stay
 *    below the cluster's MaxArraySize; `throttle` caps each chunk's running
 *    elements (--array=0-N%T). Job ids go to jobs.txt, logs to logs/.
 * Each task asks for [slurm] cpus_per_task, and for the memory and time
 * of SlurmNeeds. */
#include <libvslam/batch/BatchPlan.h>

#include <string>
#include <vector>

namespace vslam::batch
{
/** What one task of a kind asks the cluster for. */
struct SlurmNeeds
{
	int memMiB = 0;
	int timeMinutes = 0;
	std::string basis;  //!< "configured", "measured on N finished tasks" or "default (nothing measured)"
};

/** The memory and time of one task of \a kinds: [slurm] mem_mib and
 * time_minutes when set; else from the tasks of those kinds already done
 * (their metrics.txt: 1.5 x the largest peak memory + 256 MiB, 2 x the
 * longest wall time + 5 min); else 4096 MiB and 120 min. */
SlurmNeeds slurmNeeds(const BatchPlan& plan, const std::vector<Task::Kind>& kinds);

/** [first, first + count) cut into chunks of at most \a maxArraySize
 * lines (array indices 0 .. size - 1 stay below MaxArraySize). */
std::vector<std::pair<size_t, size_t>> arrayChunks(size_t first, size_t count, int maxArraySize);

/** The cluster's MaxArraySize from `scontrol show config`; 1001 (Slurm's
 * default) when scontrol is not there or does not say. */
int clusterMaxArraySize();

struct SlurmSubmission
{
	std::string dir;  //!< absolute
	size_t renderings = 0, runs = 0;  //!< tasks before and after the renderings (peers count as runs)
	size_t arrays = 0;  //!< job arrays submit.sh submits (the summary job not counted)
	SlurmNeeds renderNeeds, runNeeds;
	int maxArraySize = 0;
	std::string describe() const;  //!< a few lines for the user
};

/** Writes the submission for \a plan (programs in \a binDir) into \a dir
 * (created; earlier submission files replaced). Throws std::runtime_error
 * when a file cannot be written. */
SlurmSubmission writeSlurmSubmission(const BatchPlan& plan, const std::string& binDir, const std::string& dir);

/** Runs the submission's submit.sh (sbatch must be on the PATH); its output
 * (the job ids) goes to \a log. Throws std::runtime_error on failure. */
void submitSlurmSubmission(const SlurmSubmission& submission, std::ostream& log);
}  // namespace vslam::batch

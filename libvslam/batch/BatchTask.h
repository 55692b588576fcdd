#pragma once
/** \file BatchTask.h
 * One task of a batch, self-contained and idempotent, so that it can run in
 * a local pool or as one job of a cluster array (doc/experiments.md):
 *  - Render: vslam-simul renders the scenario with vslam_simul.seed = seed;
 *  - Run: vslam on the scenario's rawlog with vslam.RANDOM_SEED = seed and
 *    the variation's overrides, then its metrics against the ground truth
 *    (metrics.txt: ATE raw and aligned, RPE over 1 s, odometry alone, kidnaps
 *    and their recovery, to 0.3 m and to the run's error level before the
 *    kidnap, wall time, peak memory), and the paper's figures of the run in
 *    vslam/figures/ (over the scenario's `world` floor plan if given).
 * A finished task leaves a `done` file holding its command line; a task
 * whose `done` matches is skipped (resume), anything else is run afresh. A
 * finished run whose metrics come from an older version of the scoring is
 * scored again from its outputs, not run again. */
#include <libvslam/batch/BatchPlan.h>

#include <map>
#include <string>

namespace vslam::batch
{
using Metrics = std::map<std::string, double>;

struct TaskOutcome
{
	bool ok = false;
	bool skipped = false;  //!< done before (resume)
	std::string message;  //!< one line for the progress report
};

/** Where the programs are: vslam and vslam-simul in \a binDir. */
TaskOutcome runTask(const BatchPlan& plan, const Task& task, const std::string& binDir);

/** The command line a task runs (also what its `done` file holds). */
std::vector<std::string> taskCommand(const BatchPlan& plan, const Task& task, const std::string& binDir);

/** A Run task's metrics.txt ("key value" lines); empty if absent. */
Metrics readMetrics(const std::string& file);
}  // namespace vslam::batch

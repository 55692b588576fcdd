#pragma once
/** \file ListedTasks.h
 * A batch's tasks as self-contained shell commands (`vslam-batch BATCH.ini
 * --task ID` with the batch's overrides): what --list-tasks prints and what
 * a cluster's job array runs, one line per array element. */
#include <libvslam/batch/BatchPlan.h>

#include <string>
#include <vector>

namespace vslam::batch
{
/** \a s as one shell word (single-quoted). */
std::string shellWord(const std::string& s);

/** vslam-batch (in \a binDir) on the plan's file with its overrides, as a
 * shell command to which a mode (--task ID, --summary) is appended. */
std::string batchCommandLine(const BatchPlan& plan, const std::string& binDir);

/** One command per task, in the plan's order: renderings, peers, runs. */
std::vector<std::string> listedTaskCommands(const BatchPlan& plan, const std::string& binDir);
}  // namespace vslam::batch

#pragma once
/** \file BatchRunner.h
 * Runs a batch's tasks on this machine, `jobs` at a time: every rendering
 * first, then the vslam runs; tasks done before are skipped (resume), a
 * failed task is reported and the others go on. */
#include <libvslam/batch/BatchPlan.h>

#include <functional>
#include <string>

namespace vslam::batch
{
struct BatchOutcome
{
	size_t done = 0, skipped = 0, failed = 0;
};

/** \a report gets one line per finished task (called under a lock). */
BatchOutcome runBatch(const BatchPlan& plan, const std::string& binDir,
	const std::function<void(const std::string& line)>& report);
}  // namespace vslam::batch

#pragma once
/** \file AllottedCpus.h
 * How many CPUs this process was given, and OpenCV's thread pool sized to
 * match, so that a cluster task (a Slurm job with --cpus-per-task) or a
 * process pinned with taskset does not start a thread per core of the
 * whole machine. */

namespace vslam
{
/** The CPUs of this process's affinity mask (what Slurm's task/affinity,
 * a cgroup cpuset or taskset leave it), and no more than
 * SLURM_CPUS_PER_TASK when Slurm sets it (its task plugin may not pin). At
 * least 1. */
int allottedCpus();

/** Caps OpenCV's thread pool at allottedCpus() threads (a smaller pool, as
 * OPENCV_FOR_THREADS_NUM or a caller set it, stays). Every vslam tool
 * calls it first. */
void useOnlyAllottedCpus();
}  // namespace vslam

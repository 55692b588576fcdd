#pragma once
/** \file BatchSummary.h
 * The batch's results over seeds, from the runs' metrics.txt files:
 *  - summary.md: per scenario and variation, mean +- standard deviation
 *    over the seeds of ATE RMSE (raw and aligned), ATE median and mean, RPE
 *    over 1 s, odometry's ATE RMSE and median and RPE, wall time, real-time factor and peak memory; kidnaps
 *    recovered within 10 s; runs that failed or are missing;
 *  - summary.csv: one row per run with every metric;
 *  - summary_ate.png: the ATE RMSE per scenario and variation with its
 *    spread, beside odometry's. */
#include <libvslam/batch/BatchPlan.h>

#include <string>

namespace vslam::batch
{
/** Writes the three files into the plan's output folder and returns the
 * Markdown table; runs without metrics count as missing. */
std::string writeBatchSummary(const BatchPlan& plan);
}  // namespace vslam::batch

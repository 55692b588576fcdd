#pragma once
/** \file SimulatedRunFiles.h
 * Writes a simulated run: the rawlog (actions/sensory-frames format, gzip,
 * readable by rbpf-slam and rawlog-edit), the true robot path (TUM) and
 * the true landmarks ("id kind x y phi mapped_before_recording"). */
#include <libvslam/io/RawlogWriting.h>
#include <libvslam/sim/CMeasurementSimulator.h>

#include <string>

namespace vslam
{
void writeSimulatedRawlog(const SimulatedRun& run, const std::string& rawlogFile);
void writeSimulatedGroundTruth(const SimulatedRun& run, const std::string& tumFile);
void writeSimulatedLandmarks(const SimulatedRun& run, const std::string& file);
}  // namespace vslam

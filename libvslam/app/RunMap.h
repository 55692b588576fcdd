#pragma once
/** \file RunMap.h
 * The whole map of a run (final_map.vslam) from the filter and the
 * front-end, and the filter's part of a loaded one.
 */
#include <libvslam/filter/CVSlamParticleFilter.h>
#include <libvslam/frontend/CVisualFrontEnd.h>
#include <libvslam/io/LandmarkMapFile.h>
#include <libvslam/obs/CVSlamMap.h>

#include <string>

namespace vslam
{
/** The best particle's landmarks with their covariances and, with a
 * front-end, every visual landmark's appearance. */
CVSlamMap mapOfRun(const CVSlamParticleFilter& filter, const CVisualFrontEnd* frontEnd, const std::string& runId);

/** The landmarks of a (validated) map as the filter's prior map. */
LandmarkMap estimatesOf(const CVSlamMap& map);

/** A map to start from: a final_map.vslam as it is, a text map (see
 * LandmarkMapFile.h; rows without covariance get stdXY, stdPhi) as
 * landmarks without appearance. Throws InputError naming the file. */
CVSlamMap readPriorMap(const std::string& file, double stdXY, double stdPhi);
}  // namespace vslam

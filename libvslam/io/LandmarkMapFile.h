#pragma once
/** \file LandmarkMapFile.h
 * The landmark map of one particle as text, one landmark per row:
 *   id kind x y phi var_x cov_xy cov_xphi var_y cov_yphi var_phi measurements
 * kind is "pose" (visual landmark frame) or "point" (range-bearing beacon;
 * phi and its covariances are 0). */
#include <libvslam/filter/CLandmarkIndex.h>
#include <libvslam/filter/CVSlamParticle.h>

#include <string>

namespace vslam
{
void writeLandmarkMap(
	const std::string& file, const CLandmarkIndex& index, const LandmarkBank& bank);
}  // namespace vslam

#pragma once
/** \file ParticleLandmarkMap.h
 * One particle's landmarks as a plain landmark map (io/LandmarkMapFile's
 * rows), so the file format does not depend on the filter's types. */
#include <libvslam/filter/CLandmarkIndex.h>
#include <libvslam/filter/CVSlamParticle.h>
#include <libvslam/io/LandmarkMapFile.h>

#include <cstdint>
#include <vector>

namespace vslam
{
/** The particle's landmarks in slot order; with \a measurements, also the
 * number of measurements the filter used of each. */
LandmarkMap landmarkMapOf(
	const CLandmarkIndex& index, const LandmarkBank& bank, std::vector<uint64_t>* measurements = nullptr);
}  // namespace vslam

#pragma once
#include <libvslam/models/LandmarkTypes.h>

#include <cstddef>

namespace vslam
{
/** A measurement of a landmark the filter already holds, with its slot in
 * the particles' banks and the weight fraction of particles explaining it. */
struct KnownMeasurement
{
	const LandmarkMeasurement* m = nullptr;
	size_t slot = 0;
	double explainedFraction = 0;
};
}  // namespace vslam

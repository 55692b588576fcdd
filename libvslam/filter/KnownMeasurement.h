#pragma once
#include <libvslam/models/LandmarkTypes.h>

#include <cstddef>

namespace vslam
{
/** A measurement of a landmark the filter already holds, with its slot in
 * the particles' banks and the weight fractions of particles whose
 * predictive validation gate holds it: under the regular odometry noise
 * ("explained") and allowing an odometry slip ("plausible"). */
struct KnownMeasurement
{
	const LandmarkMeasurement* m = nullptr;
	size_t slot = 0;
	double explainedFraction = 0;
	double plausibleFraction = 0;
};
}  // namespace vslam

#pragma once
/** \file CVSlamParticle.h
 * One path hypothesis: the current pose, the path so far (shared with the
 * particle's ancestors) and its bank of landmark Kalman filters (shared
 * copy-on-write with the particles it was resampled with). Copying a
 * particle costs O(1).
 */
#include <libvslam/filter/PathHistory.h>
#include <libvslam/filter/PersistentArray.h>
#include <libvslam/models/LandmarkTypes.h>

namespace vslam
{
using LandmarkBank = PersistentArray<LandmarkEstimate>;

struct CVSlamParticle
{
	se2::Pose pose{0, 0, 0};
	PathHistory path;
	LandmarkBank bank;
};
}  // namespace vslam

#pragma once
/** \file MapError.h
 * The map's error against a ground-truth landmark file (the simulators' and
 * mrclam2rawlog's `_landmarks.txt`): landmarks matched by kind and ID, the
 * position error of each (after an optional SE(2) transform, e.g. the
 * trajectory's alignment), and the heading error of pose landmarks. */
#include <libvslam/eval/ErrorSummary.h>
#include <libvslam/io/LandmarkMapFile.h>
#include <libvslam/models/SE2.h>

namespace vslam
{
struct MapErrorStats
{
	size_t estimated = 0, truth = 0, matched = 0;
	ErrorSummary position;  //!< m, over the matched landmarks
	size_t poses = 0;  //!< matched pose landmarks (with a heading)
	double headingRmse = 0;  //!< rad, over those
};

/** \a transform is applied to the estimated landmarks first. */
MapErrorStats computeMapError(
	const LandmarkMap& estimate, const LandmarkMap& truth, const se2::Pose& transform = {0, 0, 0});
}  // namespace vslam

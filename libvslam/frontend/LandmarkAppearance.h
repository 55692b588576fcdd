#pragma once
/** \file LandmarkAppearance.h
 * A front-end landmark to and from its record in a saved map (CVSlamMap):
 * points, depth stds, stored descriptor codes (bytes as they are, no
 * re-encoding), bookkeeping and scale estimate. What belongs to one run's
 * odometry or clock (the last reported recognition, misses in a row, the
 * scale track's open pair) is not kept.
 */
#include <libvslam/frontend/VisualLandmarkModel.h>
#include <libvslam/obs/CVSlamMap.h>

namespace vslam
{
CVSlamMap::TLandmarkAppearance appearanceOf(const VisualLandmarkModel& landmark);

/** The landmark a record describes; `scaleSettings` given (scale
 * refinement on), its scale track resumes from the record's estimate.
 * The record must have passed CVSlamMap::validate(). */
VisualLandmarkModel landmarkOf(
	const CVSlamMap::TLandmarkAppearance& record, const TScaleTrackOptions* scaleSettings);
}  // namespace vslam

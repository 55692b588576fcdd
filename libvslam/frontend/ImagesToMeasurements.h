#pragma once
/** \file ImagesToMeasurements.h
 * Puts the front-end into a rawlog stream: the camera images of a sensory
 * frame are replaced by the observations the front-end makes of them
 * (landmark measurements and creations, heading changes); everything else
 * stays. Used by
 * the vslam app (images in, one run) and by vslam-frontend (image rawlog
 * in, measurement rawlog out).
 */
#include <libvslam/frontend/CVisualFrontEnd.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>

#include <string>

namespace vslam
{
struct ImagesToMeasurementsResult
{
	size_t images = 0, measurements = 0, created = 0, pruned = 0, headingChanges = 0;
};

/** `where` names the rawlog entry in errors. Throws InputError when an
 * image cannot be loaded (naming the image file) or its calibration is
 * unusable. */
ImagesToMeasurementsResult replaceImagesWithMeasurements(
	CVisualFrontEnd& frontEnd, mrpt::obs::CSensoryFrame& frame, const mrpt::poses::CPose2D& odometryPose,
	const std::string& where);
}  // namespace vslam

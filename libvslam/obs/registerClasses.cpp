/** Registers vslam's observation classes and its saved map with MRPT's class
 * registry when the shared library is loaded, so stock MRPT tools can read
 * rawlogs containing them: LD_PRELOAD=libvslam_obs.so rawlog-edit --info -i file.rawlog */
#include <libvslam/obs/CObservationHeadingChange.h>
#include <libvslam/obs/CObservationLandmarkCreated.h>
#include <libvslam/obs/CObservationVisualLandmark.h>
#include <libvslam/obs/CVSlamMap.h>
#include <libvslam/obs/registerClasses.h>
#include <mrpt/core/initializer.h>

MRPT_INITIALIZER(registerAllClasses_vslam_obs)
{
	vslam::registerObservationClasses();
}

void vslam::registerObservationClasses()
{
	using mrpt::rtti::registerClass;
	registerClass(CLASS_ID(vslam::CObservationVisualLandmark));
	registerClass(CLASS_ID(vslam::CObservationLandmarkCreated));
	registerClass(CLASS_ID(vslam::CObservationHeadingChange));
	registerClass(CLASS_ID(vslam::CVSlamMap));
}

#include "ImageBufferAllocation.h"

#include <cstdlib>  // defines __GLIBC__ on glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace vslam
{
void keepImageBuffersInTheProcess()
{
#if defined(__GLIBC__)
	// 32 MiB is glibc's largest dynamic mmap threshold on 64-bit systems: a
	// 1280x960 float image (SIFT's first octave of a 640x480 image) is 4.7 MiB.
	constexpr int kMmapThreshold = 32 * 1024 * 1024;
	// A free heap top up to this size stays in the process: SIFT's whole
	// scale space of a 640x480 image is about 70 MiB.
	constexpr int kTrimThreshold = 256 * 1024 * 1024;
	mallopt(M_MMAP_THRESHOLD, kMmapThreshold);
	mallopt(M_TRIM_THRESHOLD, kTrimThreshold);
#endif
}
}  // namespace vslam

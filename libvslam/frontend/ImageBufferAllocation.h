#pragma once
/** \file ImageBufferAllocation.h
 * How the process allocates the front-end's per-image buffers.
 *
 * OpenCV's SIFT allocates its scale space (megabytes of float images) for
 * every image and frees it at the end. glibc's malloc by default serves
 * blocks that large with mmap, or from the heap's top and then gives that
 * top back to the system once more than twice the block is free there; the
 * next image then page-faults the same megabytes in again. Whether that
 * happens depends on what else lives in the heap between images: keeping the
 * previous image's features (the heading change) made SIFT 1.4-1.9x slower
 * on the demo rawlog (one core: 38.7-53.0 against 28.0-28.6 ms per image,
 * page faults and first writes into fresh pages; 23.5-24.3 ms with this).
 * The processes that run the front-end call this once
 * at start; it keeps such buffers in the heap and the heap's free top in the
 * process, so each image reuses the pages of the last. The peak resident memory hardly changes (the buffers are
 * resident while SIFT runs anyway: on the demo 100.2 MiB with it against
 * 99.1-99.4 without, 97.5 either way without the heading change);
 * what the process holds between images rises to that peak. */

namespace vslam
{
/** Sets glibc's mmap and trim thresholds so that per-image buffers up to
 * tens of megabytes are reused, not returned to the system and faulted back.
 * Process-wide (mallopt); call once from main(), before the front-end runs.
 * Does nothing on a C library without mallopt. */
void keepImageBuffersInTheProcess();
}  // namespace vslam

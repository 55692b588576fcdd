#pragma once
/** \file IsolatedRawlogCheck.h
 * Reads a rawlog once in a child process, so that corrupt bytes which make
 * MRPT's own deserializers crash (null pointers), hang (sampling billions of
 * particles) or allocate gigabytes (a corrupt count inside an object) hit the
 * child, not the run. The child reports each top-level entry before reading
 * it; the parent watches its memory and time, and names the entry the child
 * did not survive. Our own reader guards what it can see from outside an
 * object (container counts, odometry values); this covers what only MRPT's
 * code inside an object reads (found by fuzzing, doc/reliability.md).
 */
#include <cstdint>
#include <optional>
#include <string>

namespace vslam
{
/** What reading one entry may cost before the check calls it corrupt. */
struct TIsolatedReadOptions
{
	/** Wall time without progress to the next entry. */
	double maxSecondsPerEntry = 60.0;
	/** Memory the child may add to what it inherited (resident bytes). */
	uint64_t maxBytesPerEntry = uint64_t(2) << 30;
};

/** The first entry MRPT's deserialization does not survive. */
struct UnreadableEntry
{
	size_t entry = 0;  //!< top-level object index, as CRawlogReader counts
	std::string why;   //!< e.g. "MRPT's deserializer crashed on it (Segmentation fault)"
};

/** Reads every object of the rawlog in a child process. Returns the first
 * entry whose reading crashed the child, exceeded a limit, or ended it in
 * any other way, or nullopt when the child read to the end or stopped at an
 * ordinary input error (which the caller's own reading then reports).
 * Throws InputError only if the child process cannot be started. */
std::optional<UnreadableEntry> findUnreadableEntry(
	const std::string& rawlogFile, const TIsolatedReadOptions& limits = {});
}  // namespace vslam

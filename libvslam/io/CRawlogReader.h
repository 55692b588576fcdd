#pragma once
/** \file CRawlogReader.h
 * Streams an MRPT rawlog (plain or gzip) in either format as filter steps:
 *  - format #1 (actions / sensory frames): each (CActionCollection,
 *    CSensoryFrame) pair is one step;
 *  - format #2 (observations): each CObservationOdometry becomes an
 *    odometry increment (difference to the previous absolute reading) and
 *    consecutive other observations with the same timestamp are grouped
 *    into one sensory frame (one image's measurements).
 * A clean end of file ends the stream; anything else (missing file,
 * truncated or corrupt data, unknown classes, non-finite odometry) throws
 * InputError naming the file and the entry.
 */
#include <libvslam/io/IsolatedRawlogCheck.h>
#include <mrpt/core/Clock.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace vslam
{
class CCheckedGzInputStream;

/** One filter step read from a rawlog. */
struct RawlogStep
{
	/** Index (0-based) of the step's first object in the file. */
	size_t entry = 0;
	/** Odometry (may be null: no motion reported). */
	mrpt::obs::CActionCollection::Ptr action;
	/** Observations (never null, may be empty). */
	mrpt::obs::CSensoryFrame::Ptr sf;
	/** The first observation's timestamp, else the action's. */
	mrpt::Clock::time_point timestamp{};
};

class CRawlogReader
{
   public:
	/** Opens the rawlog; throws InputError if it cannot be read. Also points
	 * MRPT's external-image path at "<dir>/<name>_Images" (the folder
	 * MRPT's rawlog-edit uses; whose own detection in 2.5 drops a "/").
	 * With \a isolation (the default), the whole file is first read once in
	 * a child process (IsolatedRawlogCheck.h): an entry whose bytes crash,
	 * hang or exhaust MRPT's deserializers there is an InputError naming it
	 * when reading gets to it, instead of a crash of this process. */
	explicit CRawlogReader(
		const std::string& fileName, std::optional<TIsolatedReadOptions> isolation = TIsolatedReadOptions());
	~CRawlogReader();

	/** The next step, or false at the end of the file. */
	bool next(RawlogStep& step);

	const std::string& fileName() const { return m_fileName; }
	/** Share of the file read so far, in [0, 1]. */
	double progress() const;
	/** Objects read so far. */
	size_t objectsRead() const { return m_objects; }
	size_t actionFrameSteps() const { return m_format1Steps; }
	size_t observationSteps() const { return m_format2Steps; }
	/** Objects of other classes that were skipped. */
	size_t skippedObjects() const { return m_skipped; }

	/** Reads every remaining object without grouping them into steps,
	 * calling \a beforeEach with each one's entry index before reading it
	 * (what the isolated check's child process does). Throws as next(). */
	void scanObjects(const std::function<void(size_t entry)>& beforeEach);

	/** The external-images folder of a rawlog file. */
	static std::string imagesDirectory(const std::string& rawlogFile);

   private:
	std::string m_fileName;
	std::unique_ptr<CCheckedGzInputStream> m_stream;
	std::unique_ptr<mrpt::serialization::CArchive> m_archive;
	mrpt::serialization::CSerializable::Ptr m_pending;  //!< read ahead
	size_t m_pendingEntry = 0;
	size_t m_objects = 0, m_skipped = 0, m_format1Steps = 0, m_format2Steps = 0;
	std::optional<mrpt::poses::CPose2D> m_lastOdometry;
	bool m_eof = false;
	/** Found by the isolated check: reading stops there with an error. */
	std::optional<UnreadableEntry> m_unreadable;

	/** Next object or nullptr at a clean end of file. */
	mrpt::serialization::CSerializable::Ptr readObject(size_t& entry);
	/** Rejects a container whose element count cannot fit in the rest of
	 * the file (corrupt data that would make MRPT allocate gigabytes). */
	void checkElementCount(size_t entry);
	void checkOdometry(const mrpt::obs::CActionCollection& a, size_t entry) const;
	[[noreturn]] void fail(size_t entry, const std::string& what) const;
};
}  // namespace vslam

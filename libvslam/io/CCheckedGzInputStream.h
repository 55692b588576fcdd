#pragma once
/** \file CCheckedGzInputStream.h
 * A read-only MRPT stream over a gzip (or plain) file that reports damage.
 * MRPT's CFileGZInputStream returns (size_t)-1 on corrupt compressed data,
 * which CArchive then takes for a clean end of file, and it cannot tell a
 * gzip file cut short from a complete one. This stream throws InputError
 * naming the file in both cases, so a damaged rawlog is never read as a
 * shorter valid one.
 */
#include <mrpt/io/CStream.h>

#include <cstdint>
#include <string>

namespace vslam
{
class CCheckedGzInputStream : public mrpt::io::CStream
{
   public:
	/** Opens the file; throws InputError if it cannot be read. */
	explicit CCheckedGzInputStream(const std::string& fileName);
	~CCheckedGzInputStream() override;
	CCheckedGzInputStream(const CCheckedGzInputStream&) = delete;
	CCheckedGzInputStream& operator=(const CCheckedGzInputStream&) = delete;

	size_t Read(void* buffer, size_t count) override;
	size_t Write(const void*, size_t) override;
	uint64_t Seek(int64_t, mrpt::io::CStream::TSeekOrigin) override;
	/** Size of the file on disk. */
	uint64_t getTotalBytesCount() const override { return m_fileSize; }
	/** The next \p count bytes (fewer at the end of the file) without
	 * consuming them: the following Read() calls return them again. */
	std::string peek(size_t count);
	/** An upper bound of the uncompressed bytes still to be read: exact for
	 * a plain file, from deflate's maximum ratio for a gzip one. Used to
	 * reject element counts in corrupt data before anything allocates them. */
	uint64_t remainingBytesBound() const;
	/** Uncompressed bytes read so far. */
	uint64_t getPosition() const override { return m_position; }
	/** Bytes of the file consumed so far (for progress reports). */
	uint64_t filePosition() const;
	std::string getStreamDescription() const override { return m_fileName; }
	/** The error last thrown by Read(), "" if none (MRPT's CArchive turns
	 * errors at object boundaries into an end-of-file exception). */
	const std::string& lastError() const { return m_lastError; }

   private:
	std::string m_fileName;
	void* m_gz = nullptr;  //!< gzFile
	uint64_t m_fileSize = 0, m_position = 0;
	std::string m_peeked;  //!< read ahead by peek(), not yet returned
	size_t readFromFile(unsigned char* out, size_t count);
	std::string m_lastError;
};
}  // namespace vslam

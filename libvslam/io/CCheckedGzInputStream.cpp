#include <libvslam/core/InputError.h>
#include <libvslam/io/CCheckedGzInputStream.h>
#include <zlib.h>

#include <algorithm>
#include <climits>
#include <filesystem>

using namespace vslam;

CCheckedGzInputStream::CCheckedGzInputStream(const std::string& fileName)
	: m_fileName(fileName)
{
	namespace fs = std::filesystem;
	std::error_code ec;
	const fs::file_status status = fs::status(fileName, ec);
	if (!fs::exists(status)) throw InputError("cannot open '" + fileName + "': no such file");
	if (fs::is_directory(status)) throw InputError("cannot read '" + fileName + "': it is a folder, not a file");
	// The reader reads the file twice (once in an isolated process): a pipe
	// or a device cannot be read again.
	if (!fs::is_regular_file(status))
		throw InputError("cannot read '" + fileName + "': not a regular file (a pipe or a device); give a file");
	m_fileSize = fs::file_size(fileName, ec);
	if (m_fileSize == 0) throw InputError("'" + fileName + "' is empty (0 bytes)");
	m_gz = gzopen(fileName.c_str(), "rb");
	if (!m_gz) throw InputError("cannot open '" + fileName + "' for reading");
}

CCheckedGzInputStream::~CCheckedGzInputStream()
{
	if (m_gz) gzclose(static_cast<gzFile>(m_gz));
}

size_t CCheckedGzInputStream::Read(void* buffer, size_t count)
{
	auto* out = static_cast<unsigned char*>(buffer);
	const size_t fromPeeked = std::min(count, m_peeked.size());
	std::copy_n(m_peeked.data(), fromPeeked, out);
	m_peeked.erase(0, fromPeeked);
	const size_t done = fromPeeked + readFromFile(out + fromPeeked, count - fromPeeked);
	m_position += done;
	return done;
}

std::string CCheckedGzInputStream::peek(size_t count)
{
	if (m_peeked.size() < count)
	{
		const size_t have = m_peeked.size();
		m_peeked.resize(count);
		const size_t got = readFromFile(
			reinterpret_cast<unsigned char*>(m_peeked.data()) + have, count - have);
		m_peeked.resize(have + got);
	}
	return m_peeked.substr(0, count);
}

uint64_t CCheckedGzInputStream::remainingBytesBound() const
{
	auto* gz = static_cast<gzFile>(m_gz);
	if (gzdirect(gz)) return m_fileSize > m_position ? m_fileSize - m_position : 0;
	// Deflate expands at most 1032:1; zlib may hold decompressed bytes that
	// gzoffset() already counts as consumed (its buffers are far below 1 MiB).
	const uint64_t consumed = filePosition();
	const uint64_t compressedLeft = m_fileSize > consumed ? m_fileSize - consumed : 0;
	return compressedLeft * 1032 + (1u << 20) + m_peeked.size();
}

size_t CCheckedGzInputStream::readFromFile(unsigned char* out, size_t count)
{
	auto* gz = static_cast<gzFile>(m_gz);
	size_t done = 0;
	while (done < count)
	{
		const unsigned chunk =
			static_cast<unsigned>(std::min<size_t>(count - done, INT_MAX));
		const int n = gzread(gz, out + done, chunk);
		int err = Z_OK;
		const char* msg = gzerror(gz, &err);
		// zlib hands out what it decoded before a cut: that is still data,
		// and the error comes with the next read.
		if (n > 0) done += static_cast<size_t>(n);
		if (n < 0 || (err != Z_OK && err != Z_STREAM_END))
		{
			// zlib reports a gzip file cut short as Z_BUF_ERROR.
			const std::string at = " (after " + std::to_string(m_position + done) + " uncompressed bytes)";
			m_lastError = err == Z_BUF_ERROR
				? "'" + m_fileName + "' is truncated: the compressed data ends early" + at
				: "'" + m_fileName + "' is corrupt: " + (msg ? msg : "read error") + at;
			if (n > 0) break;
			throw InputError(m_lastError);
		}
		if (n == 0) break;  // end of file
	}
	return done;
}

uint64_t CCheckedGzInputStream::filePosition() const
{
	const auto off = gzoffset(static_cast<gzFile>(m_gz));
	return off < 0 ? 0 : static_cast<uint64_t>(off);
}

size_t CCheckedGzInputStream::Write(const void*, size_t)
{
	throw std::logic_error("CCheckedGzInputStream is read-only");
}

uint64_t CCheckedGzInputStream::Seek(int64_t, mrpt::io::CStream::TSeekOrigin)
{
	throw std::logic_error("CCheckedGzInputStream cannot seek");
}

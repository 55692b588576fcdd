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
	std::error_code ec;
	if (!std::filesystem::is_regular_file(fileName, ec))
		throw InputError("cannot open '" + fileName + "': no such file");
	m_fileSize = std::filesystem::file_size(fileName, ec);
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
		if (n < 0 || (err != Z_OK && err != Z_STREAM_END))
		{
			// zlib reports a gzip file cut short as Z_BUF_ERROR.
			const std::string at =
				" (after " + std::to_string(m_position + done) + " uncompressed bytes)";
			m_lastError = err == Z_BUF_ERROR
				? "'" + m_fileName + "' is truncated: the compressed data ends early" + at
				: "'" + m_fileName + "' is corrupt: " + (msg ? msg : "read error") + at;
			throw InputError(m_lastError);
		}
		if (n == 0) break;  // end of file
		done += static_cast<size_t>(n);
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

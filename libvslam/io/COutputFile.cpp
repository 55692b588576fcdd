#include <libvslam/core/OutputError.h>
#include <libvslam/io/COutputFile.h>

#include <cerrno>
#include <cstdarg>
#include <cstring>

using namespace vslam;

COutputFile::COutputFile(std::string file, Mode mode)
	: m_file(std::move(file)), m_writtenFile(mode == Mode::Atomic ? m_file + ".tmp" : m_file), m_mode(mode)
{
	m_f = std::fopen(m_writtenFile.c_str(), "wb");
	if (!m_f) fail("cannot create", errno);
}

COutputFile::~COutputFile()
{
	if (!m_f) return;
	std::fclose(m_f);
	if (m_mode == Mode::Atomic) std::remove(m_writtenFile.c_str());
}

void COutputFile::fail(const char* what, int error) const
{
	throw OutputError(std::string(what) + " output file '" + m_file + "': " +
		(error ? std::strerror(error) : "unknown error"));
}

void COutputFile::print(const char* format, ...)
{
	va_list args;
	va_start(args, format);
	errno = 0;
	const int n = std::vfprintf(m_f, format, args);
	va_end(args);
	if (n < 0 || std::ferror(m_f)) fail("cannot write", errno);
}

void COutputFile::write(const std::string& text)
{
	errno = 0;
	if (std::fwrite(text.data(), 1, text.size(), m_f) != text.size()) fail("cannot write", errno);
}

void COutputFile::flush()
{
	errno = 0;
	if (std::fflush(m_f) != 0 || std::ferror(m_f)) fail("cannot write", errno);
}

void COutputFile::commit()
{
	flush();
	FILE* f = m_f;
	m_f = nullptr;
	errno = 0;
	if (std::fclose(f) != 0)
	{
		const int error = errno;
		if (m_mode == Mode::Atomic) std::remove(m_writtenFile.c_str());
		fail("cannot write", error);
	}
	if (m_mode == Mode::Atomic && std::rename(m_writtenFile.c_str(), m_file.c_str()) != 0)
	{
		const int error = errno;
		std::remove(m_writtenFile.c_str());
		fail("cannot replace", error);
	}
}

#pragma once
/** \file COutputFile.h
 * One output file whose every write is checked. Two kinds:
 *  - Streamed: written and flushed as a run goes (paths, step log), so an
 *    interrupted run leaves every whole row;
 *  - Atomic: written to "FILE.tmp" and renamed over FILE by commit(), so an
 *    end-of-run file is either the old one, or absent, or whole; never
 *    half-written. Not committed (an error on the way): the temporary file
 *    is removed.
 * Any failed write, flush, close or rename throws OutputError naming the
 * file and the reason (e.g. "No space left on device").
 */
#include <cstdio>
#include <string>

namespace vslam
{
class COutputFile
{
   public:
	enum class Mode
	{
		Streamed,
		Atomic
	};

	COutputFile(std::string file, Mode mode);
	~COutputFile();
	COutputFile(const COutputFile&) = delete;
	COutputFile& operator=(const COutputFile&) = delete;

	/** printf-style write; throws OutputError. */
	void print(const char* format, ...) __attribute__((format(printf, 2, 3)));
	void write(const std::string& text);
	/** Pushes the buffer to the system; throws OutputError. */
	void flush();
	/** Flushes and closes; an Atomic file replaces FILE. Throws OutputError. */
	void commit();

	const std::string& name() const { return m_file; }

   private:
	std::string m_file, m_writtenFile;
	Mode m_mode;
	FILE* m_f = nullptr;

	[[noreturn]] void fail(const char* what, int error) const;
};
}  // namespace vslam

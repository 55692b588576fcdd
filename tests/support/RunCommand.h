#pragma once
/** \file RunCommand.h  Runs a shell command, capturing its output. */
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace vslam::testing
{
struct CommandResult
{
	int exitCode = -1;  //!< -1: did not exit normally (signal)
	std::string output;  //!< stdout and stderr, interleaved
};

inline CommandResult runCommand(const std::string& command)
{
	FILE* p = ::popen((command + " 2>&1").c_str(), "r");
	if (!p) throw std::runtime_error("popen failed: " + command);
	CommandResult r;
	std::array<char, 4096> buf{};
	size_t n = 0;
	while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.output.append(buf.data(), n);
	const int status = ::pclose(p);
	r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
	return r;
}

inline bool contains(const std::string& text, const std::string& part)
{
	return text.find(part) != std::string::npos;
}

/** \a s in single quotes, for a shell command line (a quote in it closes
 * the quotes, is escaped and opens them again). */
inline std::string quoted(const std::string& s)
{
	std::string q = "'";
	for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
	return q + "'";
}

/** Lines of a file, an unterminated last one included. */
inline size_t lineCount(const std::string& file)
{
	std::ifstream f(file);
	size_t n = 0;
	for (std::string line; std::getline(f, line);) n++;
	return n;
}

inline std::string readFile(const std::string& file)
{
	std::ifstream in(file, std::ios::binary);
	return {std::istreambuf_iterator<char>(in), {}};
}
}  // namespace vslam::testing

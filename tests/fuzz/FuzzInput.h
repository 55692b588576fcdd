/** \file FuzzInput.h
 * Small helpers shared by the fuzz targets: readers take file names, so
 * each input is written to a per-process scratch file (or folder) first. */
#pragma once
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace vslam::fuzz
{
/** A scratch path unique to this process, under $TMPDIR (or /tmp). */
inline std::string scratchPath(const std::string& name)
{
	const char* tmp = std::getenv("TMPDIR");
	return (std::filesystem::path(tmp ? tmp : "/tmp") /
		("vslam_fuzz_" + std::to_string(getpid()) + "_" + name))
		.string();
}

inline void writeBytes(const std::string& file, const uint8_t* data, size_t size)
{
	std::ofstream(file, std::ios::binary | std::ios::trunc)
		.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

/** Splits the input at lines that are exactly `separator`. */
inline std::vector<std::string> splitAtLines(
	const uint8_t* data, size_t size, const std::string& separator)
{
	const std::string text(reinterpret_cast<const char*>(data), size);
	const std::string marker = "\n" + separator + "\n";
	std::vector<std::string> parts;
	size_t start = 0;
	for (size_t at; (at = text.find(marker, start)) != std::string::npos; start = at + marker.size())
		parts.push_back(text.substr(start, at - start + 1));
	parts.push_back(text.substr(start));
	return parts;
}
}  // namespace vslam::fuzz

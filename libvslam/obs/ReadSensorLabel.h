#pragma once
/** \file ReadSensorLabel.h
 * MRPT reads a std::string as a uint32 length and then allocates it, so one
 * corrupt length asks for up to 4 GiB. Our observation classes read their
 * sensor label through this instead: same bytes on disk, a bounded length.
 */
#include <mrpt/serialization/CArchive.h>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace vslam
{
/** Longest sensor label accepted when reading (labels are names like "CAMERA1"). */
constexpr uint32_t kMaxSensorLabelBytes = 4096;

/** Reads a string written by MRPT's `operator<<(CArchive&, const std::string&)`;
 * throws std::runtime_error if its length exceeds kMaxSensorLabelBytes. */
inline void readSensorLabel(mrpt::serialization::CArchive& in, std::string& label)
{
	uint32_t n = 0;
	in >> n;
	if (n > kMaxSensorLabelBytes)
		throw std::runtime_error("sensor label of " + std::to_string(n) + " bytes (at most " +
			std::to_string(kMaxSensorLabelBytes) + "): corrupt data");
	label.resize(n);
	if (n) in.ReadBufferFixEndianness(label.data(), n);
}
}  // namespace vslam

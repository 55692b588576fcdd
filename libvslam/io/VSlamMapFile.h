#pragma once
/** \file VSlamMapFile.h
 * `final_map.vslam`: one CVSlamMap, MRPT-serialized (plain; a gzip-
 * compressed copy reads the same). Stock MRPT tools read it with
 * LD_PRELOAD=libvslam_obs.so, as they read vslam's observations.
 */
#include <libvslam/obs/CVSlamMap.h>

#include <string>

namespace vslam
{
/** Whether `file` holds a serialized object (an MRPT object header, or
 * gzip data) rather than text rows. Throws InputError if it cannot be read. */
bool isSerializedFile(const std::string& file);

/** Reads and validates a map; throws InputError naming the file if it is
 * not a vslam map, is truncated or corrupt, comes from another format
 * version, or is inconsistent. */
CVSlamMap readVSlamMap(const std::string& file);

/** Writes the map atomically (a temporary file renamed): the old file or
 * the whole new one, never half of it. Throws OutputError. */
void writeVSlamMap(const std::string& file, const CVSlamMap& map);
}  // namespace vslam

#pragma once
/** \file SharedData.h
 * Where the team's shared real data lives: `../shared/data` next to the
 * source tree, or $VSLAM_SHARED_DATA. A user's clone has none; tests that
 * need it call GTEST_SKIP() with the path they looked at. */
#include <cstdlib>
#include <filesystem>

namespace vslam::testing
{
inline std::filesystem::path sharedDataDir()
{
	if (const char* env = std::getenv("VSLAM_SHARED_DATA")) return env;
	const char* src = std::getenv("VSLAM_SOURCE_DIR");
	return std::filesystem::path(src ? src : VSLAM_SOURCE_DIR) / ".." / "shared" / "data";
}

inline std::filesystem::path mrclamDataset(int n)
{
	return sharedDataDir() / "mrclam" / ("MRCLAM_Dataset" + std::to_string(n));
}
}  // namespace vslam::testing

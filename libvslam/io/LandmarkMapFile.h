#pragma once
/** \file LandmarkMapFile.h
 * The landmark map of one particle as text, one landmark per row:
 *   id kind x y phi var_x cov_xy cov_xphi var_y cov_yphi var_phi measurements
 * kind is "pose" (visual landmark frame) or "point" (range-bearing beacon;
 * phi and its covariances are 0).
 *
 * A map to start from (localization in a known map, map continuation) is
 * read from that format, or from rows without covariance:
 *   id kind x y phi [anything]      e.g. the simulator's _landmarks.txt
 *   id x y                          a point, e.g. mrclam2rawlog's _landmarks.txt
 *   id x y phi                      a pose
 * '%' and '#' start comment lines. */
#include <libvslam/models/LandmarkTypes.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace vslam
{
using LandmarkMap = std::vector<std::pair<LandmarkKey, LandmarkEstimate>>;

/** Reads a map; rows without covariance get diag(stdXY^2, stdXY^2,
 * stdPhi^2). Throws InputError naming the file and line on a malformed
 * row or a duplicate landmark. With \a measurements, also the number of
 * measurements of each row (0 where the row has none), in the map's order. */
LandmarkMap readLandmarkMap(
	const std::string& file, double stdXY, double stdPhi, std::vector<uint64_t>* measurements = nullptr);

/** Writes the map atomically (a temporary file renamed), each row with its
 * number of measurements (\a measurements in the map's order; 0 where it is
 * shorter), and a comment line naming the run if `runId` is given; throws
 * OutputError. */
void writeLandmarkMap(const std::string& file, const LandmarkMap& map,
	const std::vector<uint64_t>& measurements, const std::string& runId = "");
}  // namespace vslam

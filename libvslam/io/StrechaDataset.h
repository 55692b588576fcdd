#pragma once
/** \file StrechaDataset.h
 * Image sets with exact camera poses in the layout of Strecha et al.'s
 * benchmark (see ../shared/data/strecha/README.md): `images/NAME` and
 * `cameras/NAME.camera`, the latter 9 lines: K (3 rows), distortion (k1 k2
 * k3), R camera-to-world (3 rows), camera centre C, image width and height.
 */
#include <Eigen/Core>

#include <string>
#include <vector>

namespace vslam
{
struct StrechaView
{
	std::string name;  //!< image file name
	std::string imageFile;  //!< full path
	Eigen::Matrix3d K;
	Eigen::Vector3d distortion;  //!< k1 k2 k3
	Eigen::Matrix3d R;  //!< camera -> world (columns: camera axes in the world)
	Eigen::Vector3d C;  //!< camera centre, world
	int width = 0, height = 0;
};

/** Every view of the folder, sorted by name; throws InputError naming the
 * file on a missing or malformed camera file or a missing image. */
std::vector<StrechaView> readStrechaDataset(const std::string& folder);
}  // namespace vslam

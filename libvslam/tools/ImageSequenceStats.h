#pragma once
/** \file ImageSequenceStats.h
 * Is an image sequence good for the visual front-end? SIFT features per
 * image, and matches (Lowe's ratio test, then the inliers of a RANSAC
 * fundamental matrix) between images `pairSeconds` apart and at revisits:
 * pairs of images taken at least `revisitMinSeconds` apart from nearly the
 * same true pose. Used on vslam-simul's rendered rawlogs (vslam-image-stats).
 */
#include <libvslam/frontend/ImageFeatures.h>
#include <libvslam/io/Trajectory.h>

#include <string>
#include <vector>

namespace vslam
{
struct TImageSequenceStatsOptions
{
	double pairSeconds = 1;  //!< each image against the first one this much later
	double revisitMinSeconds = 30;
	double revisitMaxDistance = 0.3;  //!< m between the true poses
	double revisitMaxAngle = 15 * M_PI / 180;  //!< rad
};

struct MatchStats
{
	size_t pairs = 0;
	double medianMatches = 0, medianInliers = 0;
	size_t pairsWithUnder20Inliers = 0;
};

struct ImageSequenceStats
{
	size_t images = 0;
	double minFeatures = 0, medianFeatures = 0;
	size_t imagesUnder80Features = 0;
	std::vector<size_t> featureCounts;  //!< per image, in order
	MatchStats apart, revisits;  //!< pairSeconds apart; revisits
};

/** Reads the camera images of a rawlog (either format) and the true robot
 * path (for the revisits). Throws InputError naming the file or entry. */
ImageSequenceStats computeImageSequenceStats(const std::string& rawlogFile, const Trajectory& truth,
	const CFeatureExtractor::TOptions& features, const CImageCalibration::TOptions& camera,
	const TImageSequenceStatsOptions& options = {});
}  // namespace vslam

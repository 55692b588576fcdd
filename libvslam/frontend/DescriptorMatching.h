#pragma once
/** \file DescriptorMatching.h
 * Matching two sets of descriptors: each descriptor of `a` to its nearest in
 * `b` when it passes Lowe's ratio test, each `b` kept for its best `a` only.
 * The distances come from one matrix product, |a|^2 + |b|^2 - 2 a.b, in
 * blocks of rows (2-3x faster than OpenCV's brute-force matcher on the
 * front-end's sizes); the two nearest are then measured
 * directly, so the ratio test sees distances as exact as a direct sum's.
 *
 * Both ways (optional): the pair must also pass the ratio test from b's
 * side, against b's second nearest row of a. On a self-similar texture
 * (grass, foliage) one landmark point resembles many image features;
 * taking the best of them still passes a's one-way test when the landmark
 * holds no second similar point, and a handful of such matches can agree
 * on a wrong pose.
 */
#include <opencv2/core.hpp>

#include <functional>
#include <utility>
#include <vector>

namespace vslam
{
/** Ratio-test matches from `a` to `b` (index pairs (row of a, row of b),
 * ordered by b), each `b` used once. Both CV_32F with the same columns. */
std::vector<std::pair<int, int>> matchDescriptors(const cv::Mat& a, const cv::Mat& b, double ratio);

/** Whether row i of `a` may match row j of `b`. */
using MatchFilter = std::function<bool(int i, int j)>;

/** The same among the pairs `allowed` lets through (all if null): the
 * nearest and second nearest of each row of `a` are sought among its
 * allowed rows of `b` only (a guided search, e.g. near an epipolar line);
 * a row with fewer than two allowed rows is not matched. With `bothWays`,
 * a pair (i, j) is kept only if row i is also the nearest of b's row j
 * among its allowed rows of `a`, nearer than `ratio` x the second nearest
 * (a row of b with fewer than two allowed rows of a is not matched). */
std::vector<std::pair<int, int>> matchDescriptors(
	const cv::Mat& a, const cv::Mat& b, double ratio, const MatchFilter* allowed, bool bothWays = false);
}  // namespace vslam

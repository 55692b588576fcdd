#pragma once
/** \file DescriptorMatching.h
 * Matching two sets of descriptors: each descriptor of `a` to its nearest in
 * `b` when it passes Lowe's ratio test, each `b` kept for its best `a` only.
 * The distances come from one matrix product, |a|^2 + |b|^2 - 2 a.b, in
 * blocks of rows (as fast as OpenCV's brute-force matcher on the
 * front-end's sizes, benchmarks.md); the two nearest are then measured
 * directly, so the ratio test sees distances as exact as a direct sum's.
 */
#include <opencv2/core.hpp>

#include <utility>
#include <vector>

namespace vslam
{
/** Ratio-test matches from `a` to `b` (index pairs (row of a, row of b),
 * ordered by b), each `b` used once. Both CV_32F with the same columns. */
std::vector<std::pair<int, int>> matchDescriptors(const cv::Mat& a, const cv::Mat& b, double ratio);

}  // namespace vslam

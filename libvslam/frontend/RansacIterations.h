#pragma once
/** \file RansacIterations.h
 * How long a RANSAC must run before giving up. RANSAC draws minimal
 * samples until one is all inliers; after N draws it has missed a model
 * supported by k of n points with probability (1 - P(sample all inliers))^N.
 * A caller that accepts a model only with at least k inliers can stop after
 * the N that brings that probability below 1 - confidence: a model with k
 * or more inliers would have been drawn by then, and one with fewer would
 * be rejected anyway (Fischler and Bolles 1981; Hartley and Zisserman,
 * section 4.7.1). With few matches this is far below a fixed budget: 15
 * matches, 12 inliers needed and 4-point samples need 16 draws for 99.9%,
 * where a fixed budget of 300 spends them all on a candidate that fails.
 */

namespace vslam
{
/** Draws of `sampleSize` distinct points out of `points` after which a model
 * with at least `minInliers` inliers has been drawn with probability
 * `confidence` (in (0, 1)), assuming any all-inlier sample yields it.
 * At least 1; INT_MAX when no all-inlier sample can exist (minInliers <
 * sampleSize) or the probability is too small to count. */
int ransacIterationsToFind(int minInliers, int points, int sampleSize, double confidence);
}  // namespace vslam

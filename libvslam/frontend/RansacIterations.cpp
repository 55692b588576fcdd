#include <libvslam/frontend/RansacIterations.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>

int vslam::ransacIterationsToFind(int minInliers, int points, int sampleSize, double confidence)
{
	if (sampleSize < 1 || points < sampleSize || !(confidence > 0 && confidence < 1))
		throw std::invalid_argument("ransacIterationsToFind: needs 1 <= sampleSize <= points and 0 < confidence < 1");
	if (minInliers >= points) return 1;  // every sample is all inliers
	if (minInliers < sampleSize) return INT_MAX;
	// Probability that one sample, drawn without replacement, is all inliers.
	double allInliers = 1;
	for (int i = 0; i < sampleSize; i++) allInliers *= static_cast<double>(minInliers - i) / (points - i);
	const double perDrawMiss = std::log1p(-allInliers);
	if (!(perDrawMiss < 0)) return INT_MAX;
	const double draws = std::ceil(std::log1p(-confidence) / perDrawMiss);
	return draws >= INT_MAX ? INT_MAX : static_cast<int>(std::max(1.0, draws));
}

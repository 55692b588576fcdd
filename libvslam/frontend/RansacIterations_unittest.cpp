#include <libvslam/frontend/RansacIterations.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

using vslam::ransacIterationsToFind;

TEST(RansacIterations, MatchesTheClosedFormForASmallCase)
{
	// 12 of 15, 4-point samples: P = (12*11*10*9) / (15*14*13*12) = 0.3626...
	const double p = (12.0 * 11 * 10 * 9) / (15.0 * 14 * 13 * 12);
	const int expected = static_cast<int>(std::ceil(std::log(0.001) / std::log(1 - p)));
	EXPECT_EQ(ransacIterationsToFind(12, 15, 4, 0.999), expected);
	EXPECT_EQ(expected, 16);
}

TEST(RansacIterations, GrowsWithThePointsAndTheConfidence)
{
	int previous = 0;
	for (int n = 13; n <= 60; n++)
	{
		const int it = ransacIterationsToFind(12, n, 4, 0.999);
		EXPECT_GT(it, previous) << n;
		previous = it;
	}
	EXPECT_LT(ransacIterationsToFind(12, 30, 4, 0.99), ransacIterationsToFind(12, 30, 4, 0.999));
	EXPECT_LT(ransacIterationsToFind(12, 30, 3, 0.999), ransacIterationsToFind(12, 30, 4, 0.999));
}

TEST(RansacIterations, EdgeCases)
{
	EXPECT_EQ(ransacIterationsToFind(20, 20, 4, 0.999), 1);  // every sample is all inliers
	EXPECT_EQ(ransacIterationsToFind(25, 20, 4, 0.999), 1);
	EXPECT_EQ(ransacIterationsToFind(3, 20, 4, 0.999), INT_MAX);  // no all-inlier 4-sample exists
	EXPECT_EQ(ransacIterationsToFind(4, 100000, 4, 0.999), INT_MAX);  // too rare to count
	EXPECT_THROW(ransacIterationsToFind(12, 3, 4, 0.999), std::invalid_argument);
	EXPECT_THROW(ransacIterationsToFind(12, 15, 0, 0.999), std::invalid_argument);
	EXPECT_THROW(ransacIterationsToFind(12, 15, 4, 1.0), std::invalid_argument);
	EXPECT_THROW(ransacIterationsToFind(12, 15, 4, 0.0), std::invalid_argument);
}

TEST(RansacIterations, TheBoundHoldsInSimulatedDraws)
{
	// Draw 4 of 18 points with 12 marked inliers, the bound's number of times,
	// and count the trials in which no sample was all inliers: the share must
	// be about 1 - confidence (0.05 here), far from 0.5.
	const int n = 18, k = 12, s = 4;
	const double confidence = 0.95;
	const int draws = ransacIterationsToFind(k, n, s, confidence);
	std::mt19937 rng(7);
	const int trials = 20000;
	int missed = 0;
	for (int t = 0; t < trials; t++)
	{
		bool found = false;
		for (int d = 0; d < draws && !found; d++)
		{
			std::vector<int> idx(n);
			for (int i = 0; i < n; i++) idx[i] = i;
			std::shuffle(idx.begin(), idx.end(), rng);
			found = idx[0] < k && idx[1] < k && idx[2] < k && idx[3] < k;
		}
		missed += found ? 0 : 1;
	}
	const double share = static_cast<double>(missed) / trials;
	EXPECT_LE(share, 1 - confidence + 0.006);
	// ceil() makes the bound conservative by less than one draw's worth.
	EXPECT_GE(share, (1 - confidence) * 0.5);
}

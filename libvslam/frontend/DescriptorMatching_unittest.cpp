#include <gtest/gtest.h>
#include <libvslam/frontend/DescriptorMatching.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

using vslam::matchDescriptors;

namespace
{
/** The nearest and second nearest rows of `rows` to `x`, in double
 * precision and by direct sums: {distance, distance, row of the nearest}. */
struct TwoNearest
{
	double d1 = INFINITY, d2 = INFINITY;
	int nearest = -1;
};
TwoNearest twoNearestByDirectSums(const cv::Mat& rows, const cv::Mat& x)
{
	TwoNearest t;
	for (int j = 0; j < rows.rows; j++)
	{
		const double d = cv::norm(x, rows.row(j), cv::NORM_L2);
		if (d < t.d1)
		{
			t.d2 = t.d1;
			t.d1 = d;
			t.nearest = j;
		}
		else if (d < t.d2)
			t.d2 = d;
	}
	return t;
}

/** The definition, in double precision and by direct sums: a's nearest
 * and second nearest in b, the ratio test, each b kept for its best a. */
std::vector<std::pair<int, int>> referenceMatches(const cv::Mat& a, const cv::Mat& b, double ratio)
{
	std::map<int, std::pair<double, int>> bestForB;
	for (int i = 0; i < a.rows; i++)
	{
		const auto [d1, d2, j1] = twoNearestByDirectSums(b, a.row(i));
		if (!(d1 < ratio * d2)) continue;
		auto it = bestForB.find(j1);
		if (it == bestForB.end() || d1 < it->second.first) bestForB[j1] = {d1, i};
	}
	std::vector<std::pair<int, int>> out;
	for (const auto& [j, best] : bestForB) out.emplace_back(best.second, j);
	return out;
}

/** SIFT-like descriptors: `b` random in [0, 150), and `a` with `shared`
 * rows that are b's rows 0, 3, 6... plus noise, the rest random. Some b rows
 * get two noisy copies, so "each b once" is exercised. */
void makeDescriptors(int rowsA, int rowsB, int shared, cv::Mat& a, cv::Mat& b, uint64_t seed)
{
	cv::RNG rng(seed);
	b.create(rowsB, 128, CV_32F);
	rng.fill(b, cv::RNG::UNIFORM, 0, 150);
	a.create(rowsA, 128, CV_32F);
	rng.fill(a, cv::RNG::UNIFORM, 0, 150);
	for (int i = 0; i < shared && i < rowsA; i++)
	{
		const int j = (3 * i) % rowsB;
		cv::Mat noise(1, 128, CV_32F);
		rng.fill(noise, cv::RNG::NORMAL, 0, 5 + i % 40);
		cv::Mat row = b.row(j) + noise;
		row.copyTo(a.row(i));
	}
}
}  // namespace

TEST(DescriptorMatching, AgreesWithTheDefinitionOnManySizes)
{
	// Sizes across the 256-row blocks, with b as small as 2 rows.
	const int sizes[][3] = {{1, 2, 1}, {5, 2, 3}, {40, 30, 40}, {255, 300, 200}, {256, 100, 150}, {600, 300, 400},
		{700, 50, 700}};
	uint64_t seed = 1;
	for (const auto& s : sizes)
	{
		cv::Mat a, b;
		makeDescriptors(s[0], s[1], s[2], a, b, seed++);
		for (double ratio : {0.6, 0.8, 1.0})
		{
			const auto got = matchDescriptors(a, b, ratio);
			EXPECT_EQ(got, referenceMatches(a, b, ratio)) << s[0] << "x" << s[1] << " ratio " << ratio;
		}
	}
}

TEST(DescriptorMatching, FindsTheTrueMatchesAndRejectsTheAmbiguous)
{
	cv::Mat a, b;
	makeDescriptors(200, 300, 100, a, b, 42);
	const auto got = matchDescriptors(a, b, 0.8);
	// The 100 shared rows map to b rows 0, 3, ..., 297 (distinct); the noise
	// is small against random pairs' distances, so all are found.
	int trueMatches = 0;
	for (const auto& [i, j] : got) trueMatches += (i < 100 && j == 3 * i) ? 1 : 0;
	EXPECT_EQ(trueMatches, 100);
	EXPECT_LT(got.size(), 110u);  // few random rows pass the ratio test
	// A row of b present twice in b: its copy in a is ambiguous, no match.
	cv::Mat b2 = b.clone();
	b.row(0).copyTo(b2.row(1));
	for (const auto& [i, j] : matchDescriptors(a, b2, 0.8)) EXPECT_NE(i, 0);
}

TEST(DescriptorMatching, EmptyAndInvalidInput)
{
	cv::Mat a(3, 128, CV_32F, cv::Scalar(1)), b(1, 128, CV_32F, cv::Scalar(1));
	EXPECT_TRUE(matchDescriptors(cv::Mat(0, 128, CV_32F), a, 0.8).empty());
	EXPECT_TRUE(matchDescriptors(a, b, 0.8).empty());  // no second nearest
	EXPECT_THROW(matchDescriptors(a, cv::Mat(3, 64, CV_32F, cv::Scalar(1)), 0.8), std::invalid_argument);
	EXPECT_THROW(matchDescriptors(a, cv::Mat(3, 128, CV_8U, cv::Scalar(1)), 0.8), std::invalid_argument);
	// Not continuous: a column range of a wider matrix.
	cv::Mat wideA, wideB, a2, b2;
	makeDescriptors(50, 40, 30, a2, b2, 9);
	cv::hconcat(a2, cv::Mat::zeros(50, 8, CV_32F), wideA);
	cv::hconcat(b2, cv::Mat::zeros(40, 8, CV_32F), wideB);
	EXPECT_EQ(matchDescriptors(wideA.colRange(0, 128), wideB.colRange(0, 128), 0.8), referenceMatches(a2, b2, 0.8));
}

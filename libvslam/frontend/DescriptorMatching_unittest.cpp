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

TEST(DescriptorMatching, AGuidedSearchComparesOnlyTheAllowedCandidates)
{
	cv::Mat a, b;
	makeDescriptors(60, 80, 30, a, b, 11);
	// A repeated texture: b's row 1 copies row 0, so a's copy of row 0
	// fails the ratio test unguided and passes it when row 1 is not allowed.
	b.row(0).copyTo(b.row(1));
	const auto unguided = matchDescriptors(a, b, 0.8);
	const auto isMatch = [](const std::vector<std::pair<int, int>>& m, int i, int j) {
		return std::find(m.begin(), m.end(), std::make_pair(i, j)) != m.end();
	};
	EXPECT_FALSE(isMatch(unguided, 0, 0) || isMatch(unguided, 0, 1));
	const vslam::MatchFilter notRowOne = [](int, int j) { return j != 1; };
	const auto guided = matchDescriptors(a, b, 0.8, &notRowOne);
	EXPECT_TRUE(isMatch(guided, 0, 0));
	// Everything else is as the definition has it among the allowed rows:
	// without row 1 of b, the reference gives the same matches (b's rows
	// renumbered past it).
	cv::Mat bWithout;
	cv::vconcat(b.row(0), b.rowRange(2, b.rows), bWithout);
	std::vector<std::pair<int, int>> expected;
	for (auto [i, j] : referenceMatches(a, bWithout, 0.8)) expected.emplace_back(i, j == 0 ? 0 : j + 1);
	std::sort(expected.begin(), expected.end(), [](auto x, auto y) { return x.second < y.second; });
	EXPECT_EQ(guided, expected);
	// A row with a single allowed candidate has no ratio test: no match.
	const vslam::MatchFilter onlyItsTwin = [](int i, int j) { return i != 0 || j == 0; };
	EXPECT_FALSE(isMatch(matchDescriptors(a, b, 0.8, &onlyItsTwin), 0, 0));
	// Null means no guidance.
	EXPECT_EQ(matchDescriptors(a, b, 0.8, nullptr), unguided);
}

TEST(DescriptorMatching, BothWaysAlsoTestsTheRatioFromBsSide)
{
	cv::Mat a, b;
	makeDescriptors(200, 300, 100, a, b, 5);
	const auto isMatch = [](const std::vector<std::pair<int, int>>& m, int i, int j) {
		return std::find(m.begin(), m.end(), std::make_pair(i, j)) != m.end();
	};
	// A self-similar texture: a's rows 150 and 151 are two copies of b's
	// row 0, each with small noise. From a's side each passes (b holds one
	// such row); b's row 0 keeps the nearer; from b's side its two nearest
	// are both copies: ambiguous.
	cv::RNG rng(3);
	for (int i : {150, 151})
	{
		cv::Mat noise(1, 128, CV_32F);
		rng.fill(noise, cv::RNG::NORMAL, 0, 3);
		cv::Mat row = b.row(0) + noise;
		row.copyTo(a.row(i));
	}
	// (Row 0 of a is also a copy of b's row 0, with noise 5: move it away.)
	rng.fill(a.row(0), cv::RNG::UNIFORM, 0, 150);
	const auto oneWayTwins = matchDescriptors(a, b, 0.8);
	EXPECT_TRUE(isMatch(oneWayTwins, 150, 0) || isMatch(oneWayTwins, 151, 0));
	const auto bothWaysTwins = matchDescriptors(a, b, 0.8, nullptr, true);
	for (const auto& [i, j] : bothWaysTwins) EXPECT_NE(j, 0);
	// Every other match is the one-way match that also passes the ratio test
	// from b's side, checked by direct sums in double precision.
	size_t kept = 0;
	for (const auto& [i, j] : oneWayTwins)
	{
		if (j == 0) continue;
		const auto [e1, e2, nearest] = twoNearestByDirectSums(a, b.row(j));
		const bool passes = nearest == i && e1 < 0.8 * e2;
		EXPECT_EQ(isMatch(bothWaysTwins, i, j), passes) << i << " " << j;
		kept += passes ? 1 : 0;
	}
	EXPECT_EQ(bothWaysTwins.size(), kept);
	// The true matches with moderate noise (a's rows i < 100 with noise 5 +
	// i % 40 up to 25 per value: distance about 280, against about 690 to a
	// random row) pass from both sides; the noisiest may fail either way.
	for (int i = 1; i < 100; i++)
	{
		if (5 + i % 40 > 25) continue;
		EXPECT_TRUE(isMatch(bothWaysTwins, i, 3 * i)) << i;
	}
	// Off: the one-way matches.
	EXPECT_EQ(matchDescriptors(a, b, 0.8, nullptr, false), oneWayTwins);
	// Guided: b's side compares only the allowed rows of a too. With a's row
	// 151 not allowed to match b's row 0, row 150 is unambiguous again.
	const vslam::MatchFilter notTheTwin = [](int i, int j) { return !(i == 151 && j == 0); };
	EXPECT_TRUE(isMatch(matchDescriptors(a, b, 0.8, &notTheTwin, true), 150, 0));
}

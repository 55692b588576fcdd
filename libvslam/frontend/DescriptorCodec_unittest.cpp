/** DescriptorCodec: sizes and code types of every storage, the uint4
 * square-root scale (error bound, saturation, decode without a codec), and
 * what matching sees: nearest neighbours among look-alikes, and distances
 * (the ratio test's input) in the matching space. */
#include <gtest/gtest.h>
#include <libvslam/frontend/DescriptorCodec.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace vslam;

namespace
{
/** SIFT-like rows as OpenCV makes them: a few large values and many small
 * ones, unit norm scaled to 512, clipped at 0.2 of it and renormalized. */
cv::Mat siftLikeDescriptors(std::mt19937& rng, int rows)
{
	std::exponential_distribution<float> value(1.0f);
	cv::Mat d(rows, 128, CV_32F);
	for (int r = 0; r < rows; r++)
	{
		cv::Mat row = d.row(r);
		for (int c = 0; c < 128; c++) row.at<float>(c) = std::pow(value(rng), 2.0f);
		row *= 512.0 / cv::norm(row);
		cv::min(row, 0.2 * 512, row);
		row *= 512.0 / cv::norm(row);
	}
	return d;
}

/** The same rows seen again: relative noise, renormalized. */
cv::Mat seenAgain(std::mt19937& rng, const cv::Mat& d, float relativeNoise)
{
	std::normal_distribution<float> noise(0, relativeNoise * 512 / std::sqrt(128.0f));
	cv::Mat out = d.clone();
	for (int r = 0; r < out.rows; r++)
	{
		cv::Mat row = out.row(r);
		for (int c = 0; c < 128; c++) row.at<float>(c) = std::max(0.0f, row.at<float>(c) + noise(rng));
		row *= 512.0 / cv::norm(row);
	}
	return out;
}

int nearestRow(const cv::Mat& rows, const cv::Mat& query)
{
	int best = -1;
	double bestDist = INFINITY;
	for (int r = 0; r < rows.rows; r++)
	{
		const double dist = cv::norm(rows.row(r), query, cv::NORM_L2SQR);
		if (dist < bestDist) best = r, bestDist = dist;
	}
	return best;
}
}  // namespace

TEST(DescriptorCodec, EachStorageHasItsSizeAndCodeType)
{
	std::mt19937 rng(3);
	const cv::Mat d = siftLikeDescriptors(rng, 5);
	struct Expected
	{
		DescriptorCodec::Kind kind;
		size_t bytes;
		int type, cols;
	};
	for (const Expected& e : {Expected{DescriptorCodec::Kind::Float, 512, CV_32F, 128},
			 Expected{DescriptorCodec::Kind::Uint8, 128, CV_8U, 128},
			 Expected{DescriptorCodec::Kind::Uint4, 64, CV_8U, 64},
			 Expected{DescriptorCodec::Kind::Projected, 32, CV_8S, 32}})
	{
		const DescriptorCodec codec(e.kind, 32);
		const cv::Mat codes = codec.encode(d);
		SCOPED_TRACE(DescriptorCodec::name(e.kind));
		EXPECT_EQ(codec.bytesPerDescriptor(), e.bytes);
		EXPECT_EQ(codes.type(), e.type);
		EXPECT_EQ(codes.cols, e.cols);
		EXPECT_EQ(codes.rows, 5);
		EXPECT_EQ(codes.cols * static_cast<int>(codes.elemSize()), static_cast<int>(e.bytes));
		EXPECT_EQ(DescriptorCodec::decode(codes).cols, codec.dims());
		EXPECT_EQ(DescriptorCodec::parse(DescriptorCodec::name(e.kind)), e.kind);
	}
	EXPECT_THROW(DescriptorCodec::parse("uint2"), std::invalid_argument);
}

TEST(DescriptorCodec, Uint4KeepsEachValueWithinHalfAStepOnTheRootScale)
{
	constexpr float step = DescriptorCodec::kUint4RootStep;
	const float saturation = std::pow(15 * step, 2.0f);
	cv::Mat d(1, 128, CV_32F);
	for (int c = 0; c < 128; c++) d.at<float>(c) = 200.0f * c / 127;  // 0 .. 200, past saturation
	const DescriptorCodec codec(DescriptorCodec::Kind::Uint4, 0);
	const cv::Mat decoded = DescriptorCodec::decode(codec.encode(d));
	for (int c = 0; c < 128; c++)
	{
		const float v = d.at<float>(c), back = decoded.at<float>(c);
		if (v <= saturation)
			EXPECT_LE(std::abs(std::sqrt(back) - std::sqrt(v)), step / 2 + 1e-5f) << "value " << v;
		else
			EXPECT_FLOAT_EQ(back, saturation) << "value " << v;
	}
	EXPECT_EQ(decoded.at<float>(0), 0.0f);  // zeros, most of a SIFT row, stay exact
	// Encoding is idempotent on decoded values: stored codes survive a rebuild.
	const cv::Mat again = codec.encode(decoded);
	EXPECT_EQ(cv::norm(again, codec.encode(d), cv::NORM_INF), 0.0);
}

TEST(DescriptorCodec, CompactStoragesKeepTheNearestNeighbour)
{
	// Each stored row has a look-alike (the same row with noise) next to it,
	// and the query is the row seen again with twice that noise: in the
	// matching space its nearest neighbour must be the row itself about as
	// often as with the float descriptors.
	std::mt19937 rng(11);
	constexpr int n = 250;
	const cv::Mat rows = siftLikeDescriptors(rng, n);
	cv::Mat stored;
	cv::vconcat(rows, seenAgain(rng, rows, 0.2f), stored);
	const cv::Mat queries = seenAgain(rng, rows, 0.4f);
	int floatHits = 0;
	for (int q = 0; q < n; q++) floatHits += nearestRow(stored, queries.row(q)) == q;
	for (const auto kind : {DescriptorCodec::Kind::Uint8, DescriptorCodec::Kind::Uint4})
	{
		const DescriptorCodec codec(kind, 0);
		const cv::Mat decoded = DescriptorCodec::decode(codec.encode(stored));
		const cv::Mat inMatchingSpace = codec.toMatchingSpace(queries);
		int hits = 0;
		for (int q = 0; q < n; q++) hits += nearestRow(decoded, inMatchingSpace.row(q)) == q;
		SCOPED_TRACE(DescriptorCodec::name(kind));
		// uint8 only rounds; uint4 may lose a few of the closest calls.
		const int allowedLoss = kind == DescriptorCodec::Kind::Uint8 ? n / 100 : floatHits * 3 / 100;
		EXPECT_GE(hits, floatHits - allowedLoss) << floatHits << " of " << n << " with float descriptors";
	}
	EXPECT_LT(floatHits, n);  // the look-alikes make the task a real one
	EXPECT_GE(floatHits, n * 9 / 10);
}

TEST(DescriptorCodec, Uint4ChangesMatchingDistancesByAFewPercent)
{
	// The ratio test compares distances: a true match's distance (the row
	// seen again) must not move much in the matching space.
	std::mt19937 rng(5);
	const cv::Mat rows = siftLikeDescriptors(rng, 300);
	const cv::Mat again = seenAgain(rng, rows, 0.3f);
	const DescriptorCodec codec(DescriptorCodec::Kind::Uint4, 0);
	const cv::Mat a = codec.toMatchingSpace(rows), b = codec.toMatchingSpace(again);
	std::vector<double> ratios;
	for (int r = 0; r < rows.rows; r++)
		ratios.push_back(cv::norm(a.row(r), b.row(r)) / cv::norm(rows.row(r), again.row(r)));
	std::sort(ratios.begin(), ratios.end());
	EXPECT_NEAR(ratios[ratios.size() / 2], 1.0, 0.05);  // 1.04 measured
	EXPECT_GE(ratios.front(), 0.8);  // 0.92 measured
	EXPECT_LE(ratios.back(), 1.2);  // 1.15 measured
}

TEST(DescriptorCodec, ProjectedCodesAreALinearOrthonormalProjectionRoundedToItsStep)
{
	std::mt19937 rng(5);
	constexpr int n = 300, dims = 16;
	const cv::Mat a = siftLikeDescriptors(rng, n), b = siftLikeDescriptors(rng, n);
	const DescriptorCodec codec(DescriptorCodec::Kind::Projected, dims);
	const auto project = [&](const cv::Mat& d) { return codec.toMatchingSpace(d); };
	const cv::Mat pa = project(a), pb = project(b), mean = project(0.5 * (a + b));
	ASSERT_EQ(pa.cols, dims);
	// Linear: each code is within half a step of the exact value (the mean,
	// unlike a sum, stays inside the codes' range), so the projection of the
	// mean is the mean of the projections within one step.
	EXPECT_LE(cv::norm(mean - 0.5 * (pa + pb), cv::NORM_INF), DescriptorCodec::kProjectedStep + 1e-4);
	// Orthonormal rows: a difference keeps dims/128 of its squared length on
	// average (0.125 here), and never more than all of it (plus rounding).
	double kept = 0;
	for (int r = 0; r < n; r++)
	{
		const double full = cv::norm(a.row(r) - b.row(r), cv::NORM_L2SQR);
		const double projected = cv::norm(pa.row(r) - pb.row(r), cv::NORM_L2SQR);
		EXPECT_LE(std::sqrt(projected), std::sqrt(full) + DescriptorCodec::kProjectedStep * std::sqrt(double(dims)));
		kept += projected / full;
	}
	EXPECT_NEAR(kept / n, double(dims) / 128, 0.2 * dims / 128);
	// A descriptor of another length is refused, not read past its end.
	EXPECT_THROW(codec.encode(cv::Mat::ones(3, 64, CV_32F)), std::invalid_argument);
}

/** DescriptorIndex back-ends against brute force: exact when asked to be,
 * high recall with their defaults, removed landmarks never returned,
 * incremental insertion (rebuilds, level merges) invisible in the results,
 * FLANN deterministic without touching the caller's random generator. The
 * best-bin-first tree alone is in BestBinFirstTree_unittest.cpp. */
#include <gtest/gtest.h>
#include <libvslam/frontend/DescriptorCodec.h>
#include <libvslam/frontend/DescriptorIndex.h>
#include <libvslam/frontend/FlannDescriptorIndex.h>

#include <cmath>
#include <iostream>
#include <map>
#include <random>

using namespace vslam;

namespace
{
constexpr int kRowsPerLandmark = 40;

/** SIFT-like rows: values 0..160, independent per landmark. */
cv::Mat randomDescriptors(std::mt19937& rng, int rows)
{
	std::uniform_real_distribution<float> value(0, 160);
	cv::Mat d(rows, 128, CV_32F);
	for (int r = 0; r < rows; r++)
		for (int c = 0; c < 128; c++) d.at<float>(r, c) = value(rng);
	return d;
}

cv::Mat withNoise(std::mt19937& rng, const cv::Mat& d, float sigma)
{
	std::normal_distribution<float> noise(0, sigma);
	cv::Mat out = d.clone();
	for (int r = 0; r < out.rows; r++)
		for (int c = 0; c < out.cols; c++) out.at<float>(r, c) = std::clamp(out.at<float>(r, c) + noise(rng), 0.f, 255.f);
	return out;
}

/** The brute-force answer in the codec's space over the live landmarks. */
NearestLandmarkRows bruteForce(const std::map<int64_t, cv::Mat>& codesByOwner, const float* query, int dims)
{
	NearestLandmarkRows best;
	for (const auto& [owner, codes] : codesByOwner)
		for (int r = 0; r < codes.rows; r++)
		{
			float d = 0;
			for (int c = 0; c < dims; c++) d += std::pow(codes.at<float>(r, c) - query[c], 2.f);
			if (best.count == 0 || d < best.dist[0])
			{
				best.owner[1] = best.owner[0], best.dist[1] = best.dist[0];
				best.owner[0] = owner, best.dist[0] = d;
				best.count = std::min(best.count + 1, 2);
			}
			else if (best.count == 1 || d < best.dist[1])
			{
				best.owner[1] = owner, best.dist[1] = d;
				best.count = 2;
			}
		}
	return best;
}

struct Scenario
{
	std::string index;
	int checks;  // flann; bbf: codes compared
};

void PrintTo(const Scenario& s, std::ostream* os) { *os << s.index << " checks " << s.checks; }

class DescriptorIndexScenario : public ::testing::TestWithParam<Scenario>
{
   protected:
	std::unique_ptr<DescriptorIndex> make(const DescriptorCodec& codec) const
	{
		TDescriptorSearchOptions search;
		search.index = GetParam().index;
		search.checks = GetParam().checks;
		search.bbf_compared = GetParam().checks;
		return DescriptorIndex::create(search, codec);
	}
};
class ExactDescriptorIndex : public DescriptorIndexScenario
{
};
class DefaultDescriptorIndex : public DescriptorIndexScenario
{
};

/** Exact settings (eps 0, or more checks than rows): the brute-force answer,
 * while landmarks of different sizes are added one by one (rebuilds,
 * merges), some in two blocks (a landmark added again), and removed. */
TEST_P(ExactDescriptorIndex, GivesTheBruteForceNeighbours)
{
	std::mt19937 rng(7);
	const DescriptorCodec codec(DescriptorCodec::Kind::Projected, 16);
	auto index = make(codec);
	std::map<int64_t, cv::Mat> live;
	size_t removedRows = 0;
	for (int64_t id = 1; id <= 37; id++)
	{
		const cv::Mat sift = randomDescriptors(rng, 10 + static_cast<int>(id * 7 % 50));
		index->add(id, sift);
		live[id] = codec.toMatchingSpace(sift);
		if (id % 9 == 0)
		{
			const cv::Mat more = randomDescriptors(rng, 5);
			index->add(id, more);
			cv::vconcat(live[id], codec.toMatchingSpace(more), live[id]);
		}
		if (id % 5 == 0)
		{
			index->remove(id - 3);
			removedRows += static_cast<size_t>(live[id - 3].rows);
			live.erase(id - 3);
		}
		if (id % 6 != 0) continue;
		const cv::Mat queries = codec.toMatchingSpace(randomDescriptors(rng, 20));
		const auto found = index->twoNearest(queries);
		for (int q = 0; q < queries.rows; q++)
		{
			const auto expected = bruteForce(live, queries.ptr<float>(q), codec.dims());
			ASSERT_EQ(found[q].count, 2);
			// (FLANN sums the squares in another order: float rounding)
			EXPECT_NEAR(found[q].dist[0], expected.dist[0], 1e-5 * expected.dist[0]) << "landmarks " << id << ", query " << q;
			EXPECT_NEAR(found[q].dist[1], expected.dist[1], 1e-5 * expected.dist[1]);
			EXPECT_EQ(found[q].owner[0], expected.owner[0]);
			EXPECT_EQ(found[q].owner[1], expected.owner[1]);
		}
	}
	EXPECT_EQ(index->removedRows(), removedRows);
}

/** The default approximation: a noisy copy of a stored row finds that
 * row's landmark almost always (voting tolerates the rest), and never a
 * removed landmark. These uniform random descriptors are harder than real
 * SIFT (all 16 projected dimensions independent): with noise 12 per value
 * the k-d tree finds 100%, FLANN 96% and bbf 96%; with noise 20, the k-d
 * tree 98% and FLANN 76%. */
TEST_P(DefaultDescriptorIndex, RecallsTheRightLandmarkAndSkipsRemovedOnes)
{
	std::mt19937 rng(11);
	const DescriptorCodec codec(DescriptorCodec::Kind::Projected, 16);
	auto index = make(codec);
	std::map<int64_t, cv::Mat> sift;
	for (int64_t id = 1; id <= 300; id++)
	{
		sift[id] = randomDescriptors(rng, kRowsPerLandmark);
		index->add(id, sift[id]);
	}
	for (int64_t id = 2; id <= 300; id += 10) index->remove(id);
	int right = 0, total = 0;
	for (int64_t id = 1; id <= 300; id += 7)
	{
		const auto found = index->twoNearest(codec.toMatchingSpace(withNoise(rng, sift[id], 12)));
		for (const auto& f : found)
		{
			ASSERT_GE(f.count, 1);
			for (int i = 0; i < f.count; i++) EXPECT_NE(f.owner[i] % 10, 2) << "removed landmark " << f.owner[i];
			if (id % 10 != 2)
			{
				right += f.owner[0] == id;
				total++;
			}
		}
	}
	std::cout << GetParam().index << ": the right landmark for " << right << " of " << total << " queries\n";
	EXPECT_GT(right, 0.9 * total) << right << " of " << total;
}

const TDescriptorSearchOptions kDefaults;
INSTANTIATE_TEST_SUITE_P(BackEnds, ExactDescriptorIndex,
	::testing::Values(Scenario{"flann", 100000}, Scenario{"bbf", 100000}),
	[](const auto& info) { return info.param.index; });
INSTANTIATE_TEST_SUITE_P(BackEnds, DefaultDescriptorIndex,
	::testing::Values(Scenario{"flann", kDefaults.checks}, Scenario{"bbf", kDefaults.bbf_compared}),
	[](const auto& info) { return info.param.index; });
}  // namespace

TEST(FlannDescriptorIndex, LevelsStayLogarithmicAndBuildsAreDeterministic)
{
	std::mt19937 rng(5);
	const DescriptorCodec codec(DescriptorCodec::Kind::Projected, 16);
	FlannDescriptorIndex a(codec, 4, 16), b(codec, 4, 16);
	cv::theRNG() = cv::RNG(123);
	const uint64_t callersState = cv::theRNG().state;
	for (int64_t id = 1; id <= 100; id++)
	{
		const cv::Mat sift = randomDescriptors(rng, kRowsPerLandmark);
		a.add(id, sift);
		b.add(id, sift);
		ASSERT_LE(a.levels(), 1 + std::log2(static_cast<double>(id)) / 2) << id << " landmarks";
	}
	EXPECT_EQ(cv::theRNG().state, callersState) << "the caller's generator was used";
	// Few checks make the answer depend on the random trees: both indices
	// built the same trees.
	const cv::Mat queries = codec.toMatchingSpace(randomDescriptors(rng, 200));
	const auto fa = a.twoNearest(queries), fb = b.twoNearest(queries);
	for (size_t q = 0; q < fa.size(); q++)
	{
		EXPECT_EQ(fa[q].owner[0], fb[q].owner[0]);
		EXPECT_EQ(fa[q].dist[0], fb[q].dist[0]);
	}
}

TEST(DescriptorIndex, UnknownBackEndIsRejected)
{
	TDescriptorSearchOptions search;
	search.index = "lsh";
	const DescriptorCodec codec(DescriptorCodec::Kind::Projected, 16);
	EXPECT_THROW(DescriptorIndex::create(search, codec), std::invalid_argument);
}

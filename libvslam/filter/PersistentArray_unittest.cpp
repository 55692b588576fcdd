#include <gtest/gtest.h>
#include <libvslam/filter/PersistentArray.h>

#include <random>
#include <vector>

using namespace vslam;

TEST(PersistentArray, PushAndRead)
{
	PersistentArray<int> a;
	EXPECT_TRUE(a.empty());
	for (int i = 0; i < 1000; i++) a.push_back(i * 3);
	ASSERT_EQ(a.size(), 1000u);
	for (int i = 0; i < 1000; i++) EXPECT_EQ(a[i], i * 3);
	EXPECT_EQ(a.levels(), 3u);  // 16^2 < 1000 <= 16^3
	EXPECT_THROW(a.at(1000), std::out_of_range);
}

TEST(PersistentArray, CopiesAreIndependentValues)
{
	PersistentArray<int> a;
	for (int i = 0; i < 100; i++) a.push_back(i);
	PersistentArray<int> b = a;
	EXPECT_TRUE(b.sharesRootWith(a));
	b.set(42, -1);
	b.push_back(100);
	EXPECT_EQ(a[42], 42);
	EXPECT_EQ(a.size(), 100u);
	EXPECT_EQ(b[42], -1);
	EXPECT_EQ(b[100], 100);
	a.set(7, 70);
	EXPECT_EQ(b[7], 7);
}

TEST(PersistentArray, AWriteCopiesOnlyItsPath)
{
	for (int n : {10, 1000, 100000})
	{
		PersistentArray<double> a;
		for (int i = 0; i < n; i++) a.push_back(i);
		PersistentArray<double> b = a;
		b.mutate(n / 2) = -1;
		// One new node per inner level plus the leaf: O(log16 n).
		EXPECT_EQ(b.nodesNotIn(a), a.levels() + 1u) << n;
		// A second write to the same element is in place.
		b.mutate(n / 2) = -2;
		EXPECT_EQ(b.nodesNotIn(a), a.levels() + 1u) << n;
	}
}

TEST(PersistentArray, UniqueArraysAreWrittenInPlace)
{
	PersistentArray<int> a;
	for (int i = 0; i < 300; i++) a.push_back(i);
	const int* before = &a[123];
	a.mutate(123) = 5;
	EXPECT_EQ(&a[123], before);
}

TEST(PersistentArray, MatchesAReferenceModelUnderRandomOperations)
{
	// Several versions evolve from shared ancestors; each must always equal
	// its own std::vector model.
	std::mt19937 rng(42);
	std::vector<PersistentArray<int>> versions(1);
	std::vector<std::vector<int>> models(1);
	for (int step = 0; step < 20000; step++)
	{
		const size_t v = rng() % versions.size();
		switch (rng() % 4)
		{
			case 0:
			case 1:
			{
				const int x = static_cast<int>(rng());
				versions[v].push_back(x);
				models[v].push_back(x);
				break;
			}
			case 2:
				if (!models[v].empty())
				{
					const size_t i = rng() % models[v].size();
					const int x = static_cast<int>(rng());
					versions[v].set(i, x);
					models[v][i] = x;
				}
				break;
			case 3:
				if (versions.size() < 20)
				{
					versions.push_back(versions[v]);
					models.push_back(models[v]);
				}
				else
				{
					const size_t w = rng() % versions.size();
					versions[v] = versions[w];
					models[v] = models[w];
				}
				break;
		}
	}
	for (size_t v = 0; v < versions.size(); v++)
	{
		ASSERT_EQ(versions[v].size(), models[v].size());
		for (size_t i = 0; i < models[v].size(); i++)
			ASSERT_EQ(versions[v][i], models[v][i]) << v << " " << i;
	}
}

namespace
{
struct Counted
{
	static inline int alive = 0;
	Counted() { alive++; }
	Counted(const Counted&) { alive++; }
	~Counted() { alive--; }
};
}  // namespace

TEST(PersistentArray, ReleasesEveryElement)
{
	{
		PersistentArray<Counted> a;
		for (int i = 0; i < 500; i++) a.push_back(Counted());
		PersistentArray<Counted> b = a;
		b.mutate(3);
		b.push_back(Counted());
		EXPECT_EQ(Counted::alive, 502);
	}
	EXPECT_EQ(Counted::alive, 0);
}

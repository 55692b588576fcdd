#include <gtest/gtest.h>
#include <libvslam/filter/PathHistory.h>

using namespace vslam;

TEST(PathHistory, CopiesShareTheirPastAndDivergeAfterwards)
{
	PathHistory a;
	const auto t0 = mrpt::Clock::fromDouble(100.0);
	a.push(t0, {0, 0, 0});
	a.push(t0 + std::chrono::seconds(1), {1, 0, 0});
	PathHistory b = a;
	b.push(t0 + std::chrono::seconds(2), {2, 0, 0});
	a.push(t0 + std::chrono::seconds(2), {1, 1, 0});
	const auto va = a.toVector(), vb = b.toVector();
	ASSERT_EQ(va.size(), 3u);
	ASSERT_EQ(vb.size(), 3u);
	EXPECT_EQ(va[1].pose.x, 1.0);
	EXPECT_EQ(vb[1].pose.x, 1.0);
	EXPECT_EQ(va[2].pose.y, 1.0);
	EXPECT_EQ(vb[2].pose.x, 2.0);
	EXPECT_EQ(va[0].t, t0);
}

TEST(PathHistory, VeryLongPathsAreReleasedWithoutRecursion)
{
	PathHistory p;
	for (int i = 0; i < 2000000; i++) p.push(mrpt::Clock::time_point(), {double(i), 0, 0});
	EXPECT_EQ(p.length(), 2000000u);
	p = PathHistory();  // would overflow the stack if released recursively
	EXPECT_TRUE(p.empty());
}

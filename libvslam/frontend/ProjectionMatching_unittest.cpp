#include <gtest/gtest.h>
#include <libvslam/frontend/ProjectionMatching.h>

#include <utility>
#include <vector>

using namespace vslam;

namespace
{
/** One-dimensional-looking descriptors: row i is v_i in every column, so
 * the distance between rows is |v_a - v_b| * sqrt(columns). */
cv::Mat descriptorsOf(const std::vector<float>& values)
{
	cv::Mat d(static_cast<int>(values.size()), 4, CV_32F);
	for (int i = 0; i < d.rows; i++) d.row(i).setTo(values[i]);
	return d;
}

struct Case
{
	std::vector<cv::Point2f> projected;
	std::vector<bool> valid;
	cv::Mat points;
	std::vector<bool> pointTaken;
	std::vector<cv::Point2f> features;
	cv::Mat featureDescriptors;
	std::vector<bool> featureTaken;

	std::vector<std::pair<int, int>> match(const ProjectionMatchLimits& limits) const
	{
		return matchByProjection(projected, valid, points, pointTaken, features, featureDescriptors, featureTaken, limits);
	}
};

const ProjectionMatchLimits kLimits{5.0, 0.8, 10.0};  // distances: |dv| * 2
}  // namespace

TEST(ProjectionMatching, MatchesTheNearestFeatureInTheWindowOnly)
{
	Case c;
	c.projected = {{100, 100}, {200, 100}};
	c.valid = {true, true};
	c.points = descriptorsOf({10, 20});
	c.pointTaken = {false, false};
	// Feature 0 near point 0 with its descriptor; feature 1 has point 1's
	// descriptor but lies 6 px from its projection; feature 2 has point 0's
	// descriptor far away.
	c.features = {{102, 99}, {206, 100}, {300, 300}};
	c.featureDescriptors = descriptorsOf({10.5, 20, 10});
	c.featureTaken = {false, false, false};
	const auto m = c.match(kLimits);
	ASSERT_EQ(m.size(), 1u);
	EXPECT_EQ(m[0], std::make_pair(0, 0));
	// A wider window reaches feature 1.
	ProjectionMatchLimits wide = kLimits;
	wide.radiusPx = 6.5;
	EXPECT_EQ(c.match(wide), (std::vector<std::pair<int, int>>{{0, 0}, {1, 1}}));
}

TEST(ProjectionMatching, RejectsFarDescriptorsAmbiguousWindowsTakenAndInvalidEntries)
{
	Case c;
	c.projected = {{100, 100}, {200, 100}, {300, 100}, {400, 100}, {500, 100}};
	c.valid = {true, true, true, false, true};
	c.points = descriptorsOf({10, 20, 30, 40, 50});
	c.pointTaken = {false, false, false, false, true};
	c.features = {
		{100, 101},  // point 0's pixel, descriptor 6 away: distance 12 > 10
		{200, 101}, {201, 100},  // two near point 1: distances 2 and 2.4, ratio 0.83
		{300, 101}, {301, 100},  // two near point 2, one taken
		{400, 100},  // point 3 is behind the camera
		{500, 100},  // point 4 is already matched
	};
	c.featureDescriptors = descriptorsOf({16, 21, 18.8, 30, 30.2, 40, 50});
	c.featureTaken = {false, false, false, true, false, false, false};
	const auto m = c.match(kLimits);
	// Only point 2 with its untaken feature.
	EXPECT_EQ(m, (std::vector<std::pair<int, int>>{{4, 2}}));
	// A looser ratio accepts point 1's nearer feature.
	ProjectionMatchLimits loose = kLimits;
	loose.ratio = 0.9;
	EXPECT_EQ(c.match(loose), (std::vector<std::pair<int, int>>{{1, 1}, {4, 2}}));
}

TEST(ProjectionMatching, AFeatureGoesToItsNearestPointOnly)
{
	Case c;
	c.projected = {{100, 100}, {103, 100}};
	c.valid = {true, true};
	c.points = descriptorsOf({10, 11});
	c.pointTaken = {false, false};
	c.features = {{101, 100}};
	c.featureDescriptors = descriptorsOf({10.9});
	c.featureTaken = {false};
	EXPECT_EQ(c.match(kLimits), (std::vector<std::pair<int, int>>{{0, 1}}));
}

TEST(ProjectionMatching, EmptyInputsAndAZeroRadiusFindNothingAndBadSizesThrow)
{
	Case c;
	c.projected = {{100, 100}};
	c.valid = {true};
	c.points = descriptorsOf({10});
	c.pointTaken = {false};
	c.features = {};
	c.featureDescriptors = cv::Mat(0, 4, CV_32F);
	EXPECT_TRUE(c.match(kLimits).empty());
	c.features = {{100, 100}};
	c.featureDescriptors = descriptorsOf({10});
	c.featureTaken = {false};
	EXPECT_EQ(c.match(kLimits).size(), 1u);
	ProjectionMatchLimits off = kLimits;
	off.radiusPx = 0;
	EXPECT_TRUE(c.match(off).empty());
	c.valid = {};
	EXPECT_THROW(c.match(kLimits), std::invalid_argument);
}

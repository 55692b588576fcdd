#include <gtest/gtest.h>
#include <libvslam/models/ChiSquare.h>

#include <cmath>

using namespace vslam;

TEST(ChiSquare, QuantilesMatchTables)
{
	// Reference values from standard chi-square tables.
	EXPECT_NEAR(chiSquareQuantile(0.95, 1), 3.841459, 1e-5);
	EXPECT_NEAR(chiSquareQuantile(0.95, 2), 5.991465, 1e-5);
	EXPECT_NEAR(chiSquareQuantile(0.95, 3), 7.814728, 1e-5);
	EXPECT_NEAR(chiSquareQuantile(0.999, 2), 13.815511, 1e-5);
	EXPECT_NEAR(chiSquareQuantile(0.999, 3), 16.266236, 1e-5);
	// Beyond the closed forms: a 6-DoF gate, and the 2 and 3 DoF ones against
	// exact values (1 - e^{-x/2} for 2 DoF).
	EXPECT_NEAR(chiSquareQuantile(0.95, 6), 12.591587, 1e-5);
	EXPECT_NEAR(chiSquareQuantile(0.99, 10), 23.209251, 1e-5);
	EXPECT_NEAR(chiSquareQuantile(0.999, 2), -2 * std::log(0.001), 1e-10);
	EXPECT_NEAR(chiSquareCdf(4.0, 2), 1 - std::exp(-2.0), 1e-14);
}

TEST(ChiSquare, CdfInvertsQuantile)
{
	for (int dof = 1; dof <= 12; dof++)
		for (double p : {0.01, 0.5, 0.9, 0.99999})
			EXPECT_NEAR(chiSquareCdf(chiSquareQuantile(p, dof), dof), p, 1e-9);
}

TEST(ChiSquare, RejectsBadArguments)
{
	EXPECT_THROW(chiSquareQuantile(1.0, 2), std::invalid_argument);
	EXPECT_THROW(chiSquareQuantile(0.5, 0), std::invalid_argument);
	EXPECT_THROW(chiSquareCdf(1.0, -1), std::invalid_argument);
}

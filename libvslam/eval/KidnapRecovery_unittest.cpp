#include <gtest/gtest.h>
#include <libvslam/eval/KidnapRecovery.h>

#include <cmath>

using namespace vslam;

namespace
{
/** Samples every 0.1 s: error 2 m until `back`, then 0.1 m, with a spike
 * of 1 m at `spike` (if >= 0). */
void errorTrace(double back, double spike, std::vector<double>& t, std::vector<double>& e)
{
	for (int i = 0; i <= 600; i++)
	{
		t.push_back(0.1 * i);
		const bool spiking = spike >= 0 && std::abs(t.back() - spike) < 0.05;
		e.push_back(spiking ? 1.0 : t.back() < back - 1e-9 ? 2.0 : 0.1);
	}
}
}  // namespace

TEST(KidnapRecovery, TheTimeUntilTheErrorStaysWithinTheBound)
{
	std::vector<double> t, e;
	errorTrace(33.0, -1, t, e);
	const auto r = recoveryTime(t, e, 30.0);
	ASSERT_TRUE(r.has_value());
	EXPECT_NEAR(*r, 3.0, 1e-9);
}

TEST(KidnapRecovery, ASpikeWithinTheHoldTimeRestartsIt)
{
	std::vector<double> t, e;
	errorTrace(33.0, 36.0, t, e);  // back at 33 s, lost again for a moment at 36 s
	const auto r = recoveryTime(t, e, 30.0);
	ASSERT_TRUE(r.has_value());
	EXPECT_NEAR(*r, 6.1, 1e-9);  // the run from 36.1 s on is the one that lasts
}

TEST(KidnapRecovery, NeverWithinOrNotForLongEnoughIsNoRecovery)
{
	std::vector<double> t, e;
	errorTrace(1000, -1, t, e);
	EXPECT_FALSE(recoveryTime(t, e, 30.0).has_value());
	std::vector<double> t2, e2;
	errorTrace(57.0, -1, t2, e2);  // within from 57 s, but the data end at 60 s
	EXPECT_FALSE(recoveryTime(t2, e2, 30.0).has_value());
	RecoveryCriterion shortHold;
	shortHold.hold = 2.0;
	EXPECT_NEAR(recoveryTime(t2, e2, 30.0, shortHold).value_or(-1), 27.0, 1e-9);
}

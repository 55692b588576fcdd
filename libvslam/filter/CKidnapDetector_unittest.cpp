#include <gtest/gtest.h>
#include <libvslam/filter/CKidnapDetector.h>
#include <mrpt/random/RandomGenerators.h>
#include <tests/support/Measurements.h>

using namespace vslam;
using vslam::testing::poseMeasurement;
using V = CKidnapDetector::Verdict;

namespace
{
/** Two pose landmarks; the robot is really at kTrue. */
class KidnapDetectorTest : public ::testing::Test
{
   protected:
	const se2::Pose kTrue{5, 5, 0};
	const se2::Pose kL1{6, 5, 0}, kL2{5, 6.5, M_PI / 2};
	LandmarkBank bank;
	CMotionModel model;
	COdometryAccumulator noMotion;
	CRobustLikelihood likelihood;
	std::vector<LandmarkMeasurement> storage;  // owns what evidence points to
	const mrpt::Clock::time_point t0 = mrpt::Clock::fromDouble(100);

	void SetUp() override
	{
		mrpt::random::getRandomGenerator().randomize(5);
		for (const auto& p : {kL1, kL2})
		{
			LandmarkEstimate l;
			l.mean = se2::toVector(p);
			l.cov = Eigen::Matrix3d::Identity() * 1e-4;
			bank.push_back(l);
		}
		storage.reserve(100);
	}
	mrpt::Clock::time_point at(double s) const
	{
		return t0 + std::chrono::microseconds(static_cast<int64_t>(s * 1e6));
	}
	CKidnapDetector::Evidence seen(size_t slot, const se2::Pose& z, bool explained,
		mrpt::Clock::time_point created)
	{
		storage.push_back(poseMeasurement(int64_t(slot + 1), z, 0.05, 0.02));
		return {{&storage.back(), slot, 0}, created, explained};
	}
	CKidnapDetector::Verdict feed(CKidnapDetector& d, double t,
		const std::vector<CKidnapDetector::Evidence>& ev)
	{
		const MotionPrior mp(noMotion, model);
		return d.update(at(t), ev, {mp, bank, 300, likelihood,
								   mrpt::random::getRandomGenerator()});
	}
};
}  // namespace

TEST_F(KidnapDetectorTest, FirstFrameAnchorsAndYoungLandmarksCountOnlyAgainstTheBelief)
{
	CKidnapDetector d;
	EXPECT_EQ(feed(d, 0, {}), V::Neutral);
	EXPECT_TRUE(d.anchored(at(0)));
	EXPECT_FALSE(d.anchored(at(1)));
	// A young landmark explained is no evidence: it was placed from this belief.
	EXPECT_EQ(feed(d, 1.5, {seen(0, se2::between(kTrue, kL1), true, at(1))}), V::Neutral);
	EXPECT_TRUE(d.localized());
	EXPECT_FALSE(d.anchored(at(1)));
	// Not explained, it contradicts the belief: a hypothesis starts from it.
	EXPECT_EQ(feed(d, 2, {seen(0, se2::between(kTrue, kL1), false, at(1))}), V::Unexplained);
	EXPECT_FALSE(d.localized());
	EXPECT_EQ(d.hypothesis().support(), 1u);
	// An anchored landmark explained: everything older becomes anchored.
	EXPECT_EQ(feed(d, 3, {seen(0, se2::between(kTrue, kL1), true, at(0))}), V::Localized);
	EXPECT_TRUE(d.anchored(at(2.5)));
	EXPECT_TRUE(d.localized());
}

TEST_F(KidnapDetectorTest, ConsistentUnexplainedFramesDeclareAKidnapping)
{
	CKidnapDetector d;
	feed(d, 0, {});
	const auto z1 = se2::between(kTrue, kL1), z2 = se2::between(kTrue, kL2);
	EXPECT_EQ(feed(d, 1, {seen(0, z1, false, at(0))}), V::Unexplained);
	EXPECT_FALSE(d.localized());
	EXPECT_EQ(d.hypothesis().support(), 1u);
	EXPECT_EQ(feed(d, 2, {seen(1, z2, false, at(0))}), V::Unexplained);
	EXPECT_EQ(d.hypothesis().support(), 2u);
	EXPECT_EQ(feed(d, 3, {seen(0, z1, false, at(0))}), V::Kidnapped);
	EXPECT_EQ(d.kidnapsDetected(), 1u);
	// The hypothesis sits on the true pose.
	double x = 0, y = 0;
	for (const auto& p : d.hypothesis().poses()) x += p.x, y += p.y;
	x /= d.hypothesis().poses().size();
	y /= d.hypothesis().poses().size();
	EXPECT_NEAR(x, kTrue.x, 0.05);
	EXPECT_NEAR(y, kTrue.y, 0.05);
}

TEST_F(KidnapDetectorTest, InconsistentFalseRecognitionsNeverConfirm)
{
	CKidnapDetector d;
	feed(d, 0, {});
	mrpt::random::CRandomGenerator rng(9);
	for (int f = 1; f <= 20; f++)
	{
		const se2::Pose z{rng.drawUniform(-3, 3), rng.drawUniform(-3, 3),
						  rng.drawUniform(-3, 3)};
		EXPECT_EQ(feed(d, f, {seen(f % 2, z, false, at(0))}), V::Unexplained);
		EXPECT_LE(d.hypothesis().support(), 2u);
	}
	EXPECT_EQ(d.kidnapsDetected(), 0u);
}

TEST_F(KidnapDetectorTest, OneLandmarkNeedsMoreFrames)
{
	for (const int frames : {4, 6})
	{
		CKidnapDetector d;
		d.options.single_landmark_frames = frames;
		feed(d, 0, {});
		const auto z1 = se2::between(kTrue, kL1);
		for (int f = 1; f < frames; f++)
			EXPECT_EQ(feed(d, f, {seen(0, z1, false, at(0))}), V::Unexplained) << f;
		EXPECT_EQ(feed(d, frames, {seen(0, z1, false, at(0))}), V::Kidnapped) << frames;
	}
}

TEST(KidnapDetector, OnePointLandmarkAloneNeverConfirms)
{
	// A range-bearing landmark leaves each frame's pose free on a circle
	// around it: however many frames of it a hypothesis explains, no kidnap;
	// a second point landmark, then, may confirm one.
	mrpt::random::getRandomGenerator().randomize(5);
	LandmarkBank bank;
	for (const Eigen::Vector2d& xy : {Eigen::Vector2d(3, 0), Eigen::Vector2d(0, 3)}) bank.push_back(vslam::testing::pointLandmark(xy));
	CMotionModel model;
	COdometryAccumulator noMotion;
	CRobustLikelihood likelihood;
	const se2::Pose truth{0.5, 0.5, 0.3};
	std::vector<LandmarkMeasurement> storage;
	storage.reserve(100);
	const auto seen = [&](size_t slot, const Eigen::Vector2d& p) {
		storage.push_back(vslam::testing::rangeBearingFrom(truth, int64_t(slot + 1), p));
		return CKidnapDetector::Evidence{{&storage.back(), slot, 0}, mrpt::Clock::fromDouble(0), false};
	};
	const auto feed = [&](CKidnapDetector& d, double t, const std::vector<CKidnapDetector::Evidence>& ev) {
		const MotionPrior mp(noMotion, model);
		return d.update(mrpt::Clock::fromDouble(t), ev,
			{mp, bank, 2000, likelihood, mrpt::random::getRandomGenerator()});
	};
	CKidnapDetector d;
	feed(d, 0, {});
	for (int f = 1; f <= 12; f++) EXPECT_EQ(feed(d, f, {seen(0, {3, 0})}), V::Unexplained) << f;
	EXPECT_EQ(d.kidnapsDetected(), 0u);
	V last = V::Unexplained;
	for (int f = 13; f <= 20 && last != V::Kidnapped; f++) last = feed(d, f, {seen(0, {3, 0}), seen(1, {0, 3})});
	EXPECT_EQ(last, V::Kidnapped);
}

TEST_F(KidnapDetectorTest, OneYoungLandmarkAloneNeverConfirmsTwoDo)
{
	CKidnapDetector d;
	feed(d, 0, {});
	const auto z1 = se2::between(kTrue, kL1), z2 = se2::between(kTrue, kL2);
	// Landmarks created after the last anchored explanation (at 0.5 s).
	for (int f = 1; f <= 12; f++)
		EXPECT_EQ(feed(d, f, {seen(0, z1, false, at(0.5))}), V::Unexplained) << f;
	EXPECT_EQ(d.hypothesis().support(), 12u);
	EXPECT_EQ(feed(d, 13, {seen(1, z2, false, at(0.5))}), V::Kidnapped);
}

TEST_F(KidnapDetectorTest, AnExplainedAnchoredMeasurementDropsTheHypothesis)
{
	CKidnapDetector d;
	feed(d, 0, {});
	const auto z1 = se2::between(kTrue, kL1);
	feed(d, 1, {seen(0, z1, false, at(0))});
	feed(d, 2, {seen(0, z1, false, at(0))});
	EXPECT_EQ(feed(d, 3, {seen(1, {0, 0, 0}, true, at(0))}), V::Localized);
	EXPECT_FALSE(d.hypothesis().active());
}

TEST_F(KidnapDetectorTest, ALandmarkThatToldAFalseStoryNoLongerConfirmsAlone)
{
	// Landmark 0 is recognized as if the robot stood elsewhere (its twin
	// hangs there), until landmark 1 confirms the belief.
	CKidnapDetector d;
	feed(d, 0, {});
	const se2::Pose elsewhere{3, 4, 1.0};
	const auto twinZ = se2::between(elsewhere, kL1);
	for (int f = 1; f <= 3; f++) EXPECT_EQ(feed(d, f, {seen(0, twinZ, false, at(0))}), V::Unexplained) << f;
	EXPECT_EQ(feed(d, 4, {seen(1, se2::between(kTrue, kL2), true, at(0))}), V::Localized);
	EXPECT_EQ(d.lookAlikes(), 1u);
	// The twin again, however often: no kidnap from it alone ...
	for (int f = 5; f <= 16; f++) EXPECT_EQ(feed(d, f, {seen(0, twinZ, false, at(0))}), V::Unexplained) << f;
	EXPECT_EQ(d.kidnapsDetected(), 0u);
	// ... but a second landmark that agrees with it confirms one.
	EXPECT_EQ(feed(d, 17, {seen(1, se2::between(elsewhere, kL2), false, at(0))}), V::Kidnapped);
}

TEST_F(KidnapDetectorTest, AStrayRecognitionOrTwoMarksNoLookAlike)
{
	// Fewer unexplained frames than min_unexplained_frames are a stray false
	// recognition, not a consistent story: the landmark still confirms alone.
	CKidnapDetector d;
	feed(d, 0, {});
	const auto z1 = se2::between(kTrue, kL1);
	for (int f = 1; f <= 2; f++) feed(d, f, {seen(0, {0.3, -2, 2.0}, false, at(0))});
	EXPECT_EQ(feed(d, 3, {seen(1, se2::between(kTrue, kL2), true, at(0))}), V::Localized);
	EXPECT_EQ(d.lookAlikes(), 0u);
	for (int f = 4; f <= 6; f++) EXPECT_EQ(feed(d, f, {seen(0, z1, false, at(0))}), V::Unexplained) << f;
	EXPECT_EQ(feed(d, 7, {seen(0, z1, false, at(0))}), V::Kidnapped);
}

TEST_F(KidnapDetectorTest, DisabledDetectorNeverDeclares)
{
	CKidnapDetector d;
	d.options.enabled = false;
	feed(d, 0, {});
	for (int f = 1; f < 10; f++)
		EXPECT_EQ(feed(d, f, {seen(f % 2, se2::between(kTrue, f % 2 ? kL2 : kL1), false, at(0))}),
				  V::Unexplained);
}

namespace
{
/** One landmark recognized falsely but consistently, as if the robot stood
 * at kElsewhere: a kidnap is declared, and the filter's cloud on kTrue is
 * handed over as the return hypothesis. */
class ReturnHypothesisTest : public KidnapDetectorTest
{
   protected:
	const se2::Pose kElsewhere{3, 4, 1.0};
	CKidnapDetector d;

	void declareFalseKidnap()
	{
		feed(d, 0, {});
		const auto falseZ = se2::between(kElsewhere, kL1);
		for (int f = 1; f < 6; f++) feed(d, f, {seen(0, falseZ, false, at(0))});
		ASSERT_EQ(feed(d, 6, {seen(0, falseZ, false, at(0))}), V::Kidnapped);
		const std::vector<se2::Pose> left(200, kTrue);
		d.acceptHypothesis(left, std::vector<double>(left.size(), 0.0), bank);
		ASSERT_FALSE(d.hypothesis().active());
	}
};
}  // namespace

TEST_F(ReturnHypothesisTest, AnotherLandmarkExplainedOnlyByTheLeftCloudReverts)
{
	declareFalseKidnap();
	ASSERT_TRUE(d.returnHypothesis().active());
	EXPECT_EQ(feed(d, 7, {seen(1, se2::between(kTrue, kL2), false, at(0))}), V::Reverted);
	EXPECT_EQ(d.kidnapsReverted(), 1u);
	EXPECT_EQ(d.lookAlikes(), 1u);  // the landmark that confirmed the false kidnap
	EXPECT_TRUE(d.localized());
	for (const auto& p : d.returnHypothesis().poses())
		ASSERT_LT(std::hypot(p.x - kTrue.x, p.y - kTrue.y), 0.05);
}

TEST_F(ReturnHypothesisTest, AnotherLandmarkExplainedByTheNewCloudConfirmsTheKidnap)
{
	declareFalseKidnap();
	EXPECT_EQ(feed(d, 7, {seen(1, se2::between(kElsewhere, kL2), true, at(0))}), V::Localized);
	EXPECT_FALSE(d.returnHypothesis().active());
	// A contradiction after the confirmation no longer reverts.
	EXPECT_NE(feed(d, 8, {seen(1, se2::between(kTrue, kL2), false, at(0))}), V::Reverted);
	EXPECT_EQ(d.kidnapsReverted(), 0u);
}

TEST_F(ReturnHypothesisTest, TheKidnapsOwnLandmarkOrAYoungOneNeverReverts)
{
	declareFalseKidnap();
	// The kidnap's own landmark, now seen where the left cloud expects it.
	EXPECT_NE(feed(d, 7, {seen(0, se2::between(kTrue, kL1), false, at(0))}), V::Reverted);
	// A landmark placed after the anchor: the left cloud explains it by
	// construction, so it is no evidence.
	EXPECT_NE(feed(d, 8, {seen(1, se2::between(kTrue, kL2), false, at(5.5))}), V::Reverted);
	EXPECT_TRUE(d.returnHypothesis().active());
}

TEST_F(ReturnHypothesisTest, AContradictionTheLeftCloudCannotExplainKeepsTheKidnap)
{
	declareFalseKidnap();
	const se2::Pose nowhere{-4, 9, -2.0};
	EXPECT_NE(feed(d, 7, {seen(1, se2::between(nowhere, kL2), false, at(0))}), V::Reverted);
	EXPECT_TRUE(d.returnHypothesis().active());
}

TEST_F(ReturnHypothesisTest, DisabledKeepsNoReturnHypothesis)
{
	d.options.revert_on_contradiction = false;
	declareFalseKidnap();
	EXPECT_FALSE(d.returnHypothesis().active());
	EXPECT_NE(feed(d, 7, {seen(1, se2::between(kTrue, kL2), false, at(0))}), V::Reverted);
}

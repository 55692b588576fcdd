/** The front-end on real photographs with exact poses (../shared/data/strecha;
 * skipped with a message when absent). Bounds are the goals where
 * they are met and otherwise the measured figures with a margin. */
#include <gtest/gtest.h>
#include <libvslam/tools/PosedImageEvaluation.h>
#include <tests/support/SharedData.h>

#include <algorithm>

using namespace vslam;

namespace
{
struct Summary
{
	double recognizedShare = 0, medianHeadingDeg = 0, medianTranslationPercent = 0;
};

Summary summarize(const PosedImageEvaluation& e)
{
	std::vector<double> h, t;
	for (const auto& r : e.records)
		if (r.recognized)
		{
			h.push_back(r.headingErrorDeg);
			t.push_back(100 * r.translationError / r.distance);
		}
	const auto median = [](std::vector<double> v) {
		std::sort(v.begin(), v.end());
		return v.empty() ? 1e9 : v[v.size() / 2];
	};
	return {e.records.empty() ? 0.0 : double(h.size()) / e.records.size(), median(h), median(t)};
}

std::vector<StrechaView> dataset(const std::string& name)
{
	const auto dir = vslam::testing::sharedDataDir() / "strecha" / name;
	if (!std::filesystem::exists(dir / "cameras")) return {};
	return readStrechaDataset(dir.string());
}

/** Outdoor scenes: points up to 200 units away. */
CVisualFrontEnd::TOptions outdoorOptions()
{
	CVisualFrontEnd::TOptions o;
	o.creation.max_depth = 200;
	return o;
}
}  // namespace

TEST(PosedImages, FountainP11)
{
	const auto views = dataset("fountain-P11");
	if (views.empty()) GTEST_SKIP() << "Strecha data absent (" << vslam::testing::sharedDataDir() << "/strecha)";
	const auto e = evaluatePosedImages(views, outdoorOptions(), {});
	const Summary s = summarize(e);
	EXPECT_GE(e.landmarksCreated, 6);
	EXPECT_GE(s.recognizedShare, 0.5);  // measured 0.64
	EXPECT_LE(s.medianHeadingDeg, 0.5);  // goal; measured 0.08
	EXPECT_LE(s.medianTranslationPercent, 3.0);  // measured 1.5 (2% odometry noise sets the scale)
	// Without odometry noise the geometry alone is far below 1%.
	TPosedImageEvaluationOptions exact;
	exact.odometryTranslationNoise = exact.odometryHeadingNoiseDeg = 0;
	EXPECT_LE(summarize(evaluatePosedImages(views, outdoorOptions(), exact)).medianTranslationPercent, 0.5);
}

TEST(PosedImages, CastleP30)
{
	const auto views = dataset("castle-P30");
	if (views.empty()) GTEST_SKIP() << "Strecha data absent (" << vslam::testing::sharedDataDir() << "/strecha)";
	const auto e = evaluatePosedImages(views, outdoorOptions(), {});
	const Summary s = summarize(e);
	EXPECT_GE(e.landmarksCreated, 14);  // measured 18 of 28
	EXPECT_GE(s.recognizedShare, 0.15);  // measured 0.21 (most pairs differ by > 60 deg)
	EXPECT_LE(s.medianHeadingDeg, 0.5);  // goal; measured 0.32
	EXPECT_LE(s.medianTranslationPercent, 4.0);  // measured 2.2; goal 1% not met
}

TEST(PosedImages, BadFoldersNameTheProblem)
{
	EXPECT_THROW(readStrechaDataset("/nonexistent"), std::exception);
}

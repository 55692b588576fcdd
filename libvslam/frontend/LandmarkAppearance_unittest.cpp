/** A front-end landmark through its saved-map record and back, and a saved
 * landmark into a database of the same or another descriptor storage. */
#include <gtest/gtest.h>
#include <libvslam/frontend/CLandmarkDatabase.h>
#include <libvslam/frontend/LandmarkAppearance.h>

#include <random>

using namespace vslam;

namespace
{
/** SIFT-like descriptors (values 0..160) for `n` points. */
cv::Mat siftLike(int n, unsigned seed)
{
	std::mt19937 rng(seed);
	std::uniform_int_distribution<int> value(0, 160);
	cv::Mat d(n, 128, CV_32F);
	for (int r = 0; r < n; r++)
		for (int c = 0; c < 128; c++) d.at<float>(r, c) = static_cast<float>(value(rng));
	return d;
}

VisualLandmarkModel sampleLandmark(const DescriptorCodec& codec)
{
	VisualLandmarkModel lm;
	lm.id = 4;
	lm.points = {{0.1f, 0.2f, 1.5f}, {-0.3f, 0.1f, 2.0f}, {0.4f, -0.2f, 1.8f}};
	lm.depthStd = {0.05f, 0.1f, 0.07f};
	lm.descriptors = codec.encode(siftLike(3, 1));
	lm.createdAt = 1.7e9;
	lm.createdAtOdometry = mrpt::poses::CPose2D(1, 2, 0.5);
	lm.views = 3;
	lm.reprojectionRms = 0.6;
	lm.recognitions = 11;
	lm.missesInARow = 2;
	lm.scale = CLandmarkScaleTrack(0.4, {});
	return lm;
}

CLandmarkDatabase::TOptions storing(const std::string& storage)
{
	CLandmarkDatabase::TOptions o;
	o.descriptor_storage = storage;
	return o;
}

constexpr double kMatchRatio = 0.8;
}  // namespace

TEST(LandmarkAppearance, ALandmarkComesBackAsItWasSaved)
{
	const DescriptorCodec codec(DescriptorCodec::Kind::Uint4, 32);
	const VisualLandmarkModel lm = sampleLandmark(codec);
	const auto record = appearanceOf(lm);
	EXPECT_EQ(record.descriptorBytes.size(), 3u * 64);
	const TScaleTrackOptions settings;
	const VisualLandmarkModel back = landmarkOf(record, &settings);
	EXPECT_EQ(back.id, lm.id);
	EXPECT_EQ(back.points, lm.points);
	EXPECT_EQ(back.depthStd, lm.depthStd);
	EXPECT_EQ(back.descriptors.type(), lm.descriptors.type());
	EXPECT_EQ(cv::norm(back.descriptors, lm.descriptors, cv::NORM_INF), 0);
	EXPECT_EQ(back.createdAt, lm.createdAt);
	EXPECT_EQ(back.views, lm.views);
	EXPECT_EQ(back.recognitions, lm.recognitions);
	EXPECT_EQ(back.missesInARow, 0);  // one run's streak
	EXPECT_DOUBLE_EQ(back.scale.scaleError(), lm.scale.scaleError());
	EXPECT_DOUBLE_EQ(back.scale.scaleErrorStd(), lm.scale.scaleErrorStd());
}

TEST(LandmarkAppearance, StoredCodesEnterADatabaseOfTheirStorageUnchanged)
{
	CLandmarkDatabase db(storing("uint8"), kMatchRatio);
	const DescriptorCodec codec(DescriptorCodec::Kind::Uint8, 32);
	VisualLandmarkModel lm = sampleLandmark(codec);
	const cv::Mat codes = lm.descriptors.clone();
	db.insertStored({std::move(lm)});
	ASSERT_NE(db.find(4), nullptr);
	EXPECT_EQ(cv::norm(db.find(4)->descriptors, codes, cv::NORM_INF), 0);
	EXPECT_THROW(db.insertStored({sampleLandmark(codec)}), std::invalid_argument);  // ID 4 exists
	// All or nothing: a good landmark beside a bad one does not go in.
	VisualLandmarkModel good = sampleLandmark(codec);
	good.id = 5;
	EXPECT_THROW(db.insertStored({good, sampleLandmark(codec)}), std::invalid_argument);
	EXPECT_EQ(db.find(5), nullptr);
}

TEST(LandmarkAppearance, CodesOfAnotherStorageAreConvertedWhenTheyDecodeToSiftValues)
{
	CLandmarkDatabase db(storing("uint4"), kMatchRatio);
	const DescriptorCodec uint8(DescriptorCodec::Kind::Uint8, 32);
	VisualLandmarkModel lm = sampleLandmark(uint8);
	const cv::Mat expected = DescriptorCodec(DescriptorCodec::Kind::Uint4, 32).encode(DescriptorCodec::decode(lm.descriptors));
	db.insertStored({std::move(lm)});
	EXPECT_EQ(db.find(4)->descriptors.cols, 64);
	EXPECT_EQ(cv::norm(db.find(4)->descriptors, expected, cv::NORM_INF), 0);
}

TEST(LandmarkAppearance, ProjectedCodesCannotBeConvertedToAnotherStorage)
{
	CLandmarkDatabase db(storing("uint8"), kMatchRatio);
	const DescriptorCodec projected(DescriptorCodec::Kind::Projected, 32);
	try
	{
		db.insertStored({sampleLandmark(projected)});
		ADD_FAILURE() << "no exception";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("projected to 32 dimensions"), std::string::npos) << e.what();
	}
	EXPECT_EQ(db.size(), 0u);
}

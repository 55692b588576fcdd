/** The saved map: every field through MRPT serialization, content checks,
 * and corrupt data (a huge count, a cut stream, an unknown version). */
#include <gtest/gtest.h>
#include <libvslam/obs/CVSlamMap.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>

#include <cstring>

using namespace vslam;

namespace
{
CVSlamMap sampleMap()
{
	CVSlamMap map;
	map.runId = "run-1";
	map.descriptorStorage = "uint8";
	map.hasCamera = true;
	map.camera.ncols = 320;
	map.camera.nrows = 240;
	map.camera.setIntrinsicParamsFromValues(250, 251, 160, 121);
	map.nextVisualLandmarkId = 8;
	CVSlamMap::TLandmarkEstimate pose;
	pose.id = 7;
	pose.mean = {1.5, -2.25, 0.3};
	pose.cov = {0.04, 0.001, 0.0002, 0.05, -0.0003, 0.001};
	pose.updates = 12;
	pose.measurements = 15;
	CVSlamMap::TLandmarkEstimate point;
	point.kind = 1;
	point.id = 7;  // another name space
	point.mean = {3, 4, 0};
	point.cov = {0.01, 0, 0, 0.02, 0, 0};
	map.estimates = {pose, point};
	CVSlamMap::TLandmarkAppearance a;
	a.id = 7;
	a.points = {{0.5f, 1.0f, 2.0f}, {-0.5f, 0.25f, 1.5f}};
	a.depthStd = {0.05f, 0.125f};
	a.descriptorDepth = CVSlamMap::kBytes;
	a.descriptorCols = 128;
	for (int i = 0; i < 256; i++) a.descriptorBytes.push_back(static_cast<uint8_t>(i * 7));
	a.createdAt = 1.7e9 + 0.5;
	a.createdAtOdometry = {1.0, 2.0, -0.5};
	a.views = 3;
	a.reprojectionRms = 0.75;
	a.recognitions = 9;
	a.scaleInformation = 250;
	a.scaleWeightedSum = 260;
	a.scalePairsUsed = 4;
	a.scalePairsRejected = 1;
	map.appearances = {a};
	return map;
}

mrpt::io::CMemoryStream serialized(const CVSlamMap& map)
{
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << map;
	buf.Seek(0);
	return buf;
}

CVSlamMap::Ptr readBack(mrpt::io::CMemoryStream& buf)
{
	auto arch = mrpt::serialization::archiveFrom(buf);
	return arch.ReadObject<CVSlamMap>();
}
}  // namespace

TEST(CVSlamMap, IsRegisteredAtLoadTime)
{
	EXPECT_NE(mrpt::rtti::findRegisteredClass("vslam::CVSlamMap"), nullptr);
}

TEST(CVSlamMap, EveryFieldSurvivesSerialization)
{
	const CVSlamMap map = sampleMap();
	ASSERT_NO_THROW(map.validate());
	auto buf = serialized(map);
	const auto back = readBack(buf);
	ASSERT_TRUE(back);
	EXPECT_EQ(back->runId, map.runId);
	EXPECT_EQ(back->descriptorStorage, map.descriptorStorage);
	ASSERT_TRUE(back->hasCamera);
	EXPECT_EQ(back->camera.intrinsicParams, map.camera.intrinsicParams);
	EXPECT_EQ(back->camera.ncols, 320u);
	EXPECT_EQ(back->nextVisualLandmarkId, 8);
	ASSERT_EQ(back->estimates.size(), 2u);
	for (size_t i = 0; i < 2; i++)
	{
		EXPECT_EQ(back->estimates[i].kind, map.estimates[i].kind);
		EXPECT_EQ(back->estimates[i].id, map.estimates[i].id);
		EXPECT_EQ(back->estimates[i].mean, map.estimates[i].mean);
		EXPECT_EQ(back->estimates[i].cov, map.estimates[i].cov);
		EXPECT_EQ(back->estimates[i].updates, map.estimates[i].updates);
		EXPECT_EQ(back->estimates[i].measurements, map.estimates[i].measurements);
	}
	ASSERT_EQ(back->appearances.size(), 1u);
	const auto &a = back->appearances[0], &b = map.appearances[0];
	ASSERT_EQ(a.points.size(), 2u);
	for (size_t i = 0; i < 2; i++)
		EXPECT_TRUE(a.points[i].x == b.points[i].x && a.points[i].y == b.points[i].y && a.points[i].z == b.points[i].z);
	EXPECT_EQ(a.depthStd, b.depthStd);
	EXPECT_EQ(a.descriptorDepth, b.descriptorDepth);
	EXPECT_EQ(a.descriptorCols, b.descriptorCols);
	EXPECT_EQ(a.descriptorBytes, b.descriptorBytes);
	EXPECT_EQ(a.createdAt, b.createdAt);
	EXPECT_EQ(a.createdAtOdometry, b.createdAtOdometry);
	EXPECT_EQ(a.views, b.views);
	EXPECT_EQ(a.reprojectionRms, b.reprojectionRms);
	EXPECT_EQ(a.recognitions, b.recognitions);
	EXPECT_EQ(a.scaleInformation, b.scaleInformation);
	EXPECT_EQ(a.scaleWeightedSum, b.scaleWeightedSum);
	EXPECT_EQ(a.scalePairsUsed, b.scalePairsUsed);
	EXPECT_EQ(a.scalePairsRejected, b.scalePairsRejected);
}

namespace
{
std::string validationError(const CVSlamMap& map)
{
	try
	{
		map.validate();
	}
	catch (const std::runtime_error& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(CVSlamMap, ValidateNamesTheFirstInconsistency)
{
	auto m = sampleMap();
	m.estimates[0].cov[5] = 0;
	EXPECT_EQ(validationError(m), "visual landmark 7: covariance not positive definite");
	m = sampleMap();
	m.estimates[1].mean[0] = NAN;
	EXPECT_EQ(validationError(m), "point landmark 7: a value is not finite");
	m = sampleMap();
	m.estimates.push_back(m.estimates[0]);
	EXPECT_EQ(validationError(m), "visual landmark 7 twice");
	m = sampleMap();
	m.appearances[0].id = 5;
	EXPECT_EQ(validationError(m), "visual landmark 5 has an appearance but no estimate");
	m = sampleMap();
	m.appearances[0].descriptorBytes.pop_back();
	EXPECT_EQ(validationError(m), "visual landmark 7 (appearance): descriptor bytes do not match its points");
	m = sampleMap();
	m.appearances[0].depthStd.pop_back();
	EXPECT_EQ(validationError(m), "visual landmark 7 (appearance): 1 depth stds for 2 points");
	m = sampleMap();
	m.nextVisualLandmarkId = 7;
	EXPECT_EQ(validationError(m), "visual landmark 7 is not below the next landmark ID");
	m = sampleMap();
	m.appearances[0].scaleInformation = -1;
	EXPECT_EQ(validationError(m), "visual landmark 7 (appearance): its scale estimate is not positive and finite");
}

TEST(CVSlamMap, ACutStreamThrowsAtEveryLength)
{
	auto buf = serialized(sampleMap());
	const auto* data = static_cast<const uint8_t*>(buf.getRawBufferData());
	const size_t size = buf.getTotalBytesCount();
	for (size_t cut = 0; cut < size; cut += 7)
	{
		mrpt::io::CMemoryStream part;
		part.Write(data, cut);
		part.Seek(0);
		EXPECT_ANY_THROW(readBack(part)) << "cut at " << cut << " of " << size;
	}
}

TEST(CVSlamMap, AHugeCountMeetsTheEndOfTheDataInsteadOfAllocating)
{
	CVSlamMap map = sampleMap();
	auto buf = serialized(map);
	auto* data = static_cast<uint8_t*>(buf.getRawBufferData());
	// The estimates' count follows the header, the strings, the camera and the next ID.
	mrpt::io::CMemoryStream head;
	{
		auto arch = mrpt::serialization::archiveFrom(head);
		map.estimates.clear();
		map.appearances.clear();
		arch << map;
	}
	// The empty map ends with two zero counts and the end marker.
	const size_t countPos = head.getTotalBytesCount() - 1 - 4 - 4;
	uint32_t count = 0;
	std::memcpy(&count, data + countPos, 4);
	ASSERT_EQ(count, 2u);
	const uint32_t corrupt = 0xF0000000u;
	std::memcpy(data + countPos, &corrupt, 4);
	buf.Seek(0);
	EXPECT_ANY_THROW(readBack(buf));
}

TEST(CVSlamMap, AnUnknownVersionThrows)
{
	auto buf = serialized(sampleMap());
	auto* data = static_cast<uint8_t*>(buf.getRawBufferData());
	const std::string name = "vslam::CVSlamMap";
	ASSERT_EQ(data[0], 0x80 | name.size());
	data[1 + name.size()] = 9;
	buf.Seek(0);
	try
	{
		readBack(buf);
		ADD_FAILURE() << "no exception";
	}
	catch (const std::exception& e)
	{
		EXPECT_NE(std::string(e.what()).find("unknown serialization version"), std::string::npos) << e.what();
	}
}

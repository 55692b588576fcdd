#include <gtest/gtest.h>
#include <libvslam/obs/CObservationHeadingChange.h>
#include <libvslam/obs/CObservationLandmarkCreated.h>
#include <libvslam/obs/CObservationVisualLandmark.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>
#include <cstring>

using namespace vslam;

TEST(Observations, ClassesAreRegisteredAtLoadTime)
{
	// No explicit registration call: the library's initializer did it.
	EXPECT_NE(
		mrpt::rtti::findRegisteredClass("vslam::CObservationVisualLandmark"),
		nullptr);
	EXPECT_NE(
		mrpt::rtti::findRegisteredClass("vslam::CObservationLandmarkCreated"),
		nullptr);
	EXPECT_NE(mrpt::rtti::findRegisteredClass("vslam::CObservationHeadingChange"), nullptr);
}

TEST(Observations, VisualLandmarkRoundTrip)
{
	CObservationVisualLandmark o;
	o.timestamp = mrpt::Clock::fromDouble(1700000000.25);
	o.sensorLabel = "VSLAM";
	o.landmarkID = 1234567890123LL;
	o.relPose = mrpt::poses::CPose2D(1.5, -0.25, 0.3);
	o.ProjErrRMS = 1.25;
	o.NPoints = 42;
	o.Slope = -0.01;
	o.SlopeStd = 0.004;
	o.Height = 0.035;
	o.sensorPoseOnRobot = mrpt::poses::CPose3D(0.1, 0, 0.3, 0, 0.2, 0);
	o.relPoseCov(0, 0) = 4e-4;
	o.relPoseCov(1, 1) = 9e-4;
	o.relPoseCov(2, 2) = 1e-5;
	o.relPoseCov(0, 1) = o.relPoseCov(1, 0) = -1e-4;

	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << o;
	buf.Seek(0);
	auto back = arch.ReadObject<CObservationVisualLandmark>();
	ASSERT_TRUE(back);
	EXPECT_EQ(back->timestamp, o.timestamp);
	EXPECT_EQ(back->sensorLabel, "VSLAM");
	EXPECT_EQ(back->landmarkID, o.landmarkID);
	EXPECT_EQ(back->relPose, o.relPose);
	EXPECT_EQ(back->ProjErrRMS, o.ProjErrRMS);
	EXPECT_EQ(back->NPoints, o.NPoints);
	EXPECT_EQ(back->Slope, o.Slope);
	EXPECT_EQ(back->SlopeStd, o.SlopeStd);
	EXPECT_EQ(back->Height, o.Height);
	EXPECT_EQ(back->sensorPoseOnRobot, o.sensorPoseOnRobot);
	EXPECT_EQ(back->relPoseCov, o.relPoseCov);
	EXPECT_EQ(back->exportTxtDataRow(), o.exportTxtDataRow());
	EXPECT_EQ(o.exportTxtHeader(), "landmarkID dx dy dtheta ProjErrRMS NPoints Slope Height");
}

namespace
{
/** `o` serialized as an older version: the current bytes with the version
 * byte replaced and the last `droppedBytes` before the end marker removed. */
CObservationVisualLandmark::Ptr readAsOlderVersion(const CObservationVisualLandmark& o, uint8_t version, size_t droppedBytes)
{
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << o;
	const auto* data = static_cast<const uint8_t*>(buf.getRawBufferData());
	std::vector<uint8_t> bytes(data, data + buf.getTotalBytesCount());
	const std::string name = "vslam::CObservationVisualLandmark";
	const size_t versionPos = 1 + name.size();
	EXPECT_EQ(bytes[versionPos], 3);
	bytes[versionPos] = version;
	bytes.erase(bytes.end() - 1 - static_cast<long>(droppedBytes), bytes.end() - 1);  // keep the end marker
	mrpt::io::CMemoryStream old;
	old.assignMemoryNotOwn(bytes.data(), bytes.size());
	auto oldArch = mrpt::serialization::archiveFrom(old);
	return oldArch.ReadObject<CObservationVisualLandmark>();
}
}  // namespace

TEST(Observations, VisualLandmarkOfVersionZeroReadsWithAnUnknownCovariance)
{
	// Version 0 is version 1 without the trailing covariance (9 doubles),
	// Height and SlopeStd.
	CObservationVisualLandmark o;
	o.landmarkID = 7;
	o.relPose = mrpt::poses::CPose2D(1, 2, 0.5);
	o.relPoseCov(0, 0) = 1;
	o.Height = 0.5;
	const auto back = readAsOlderVersion(o, 0, 11 * sizeof(double));
	ASSERT_TRUE(back);
	EXPECT_EQ(back->landmarkID, 7);
	EXPECT_EQ(back->relPose, o.relPose);
	EXPECT_EQ(back->relPoseCov, mrpt::math::CMatrixDouble33::Zero());
	EXPECT_EQ(back->Height, 0);
}

TEST(Observations, VisualLandmarkOfVersionOneReadsWithZeroHeight)
{
	// Version 1 is version 2 without the trailing Height (one double).
	CObservationVisualLandmark o;
	o.landmarkID = 8;
	o.relPoseCov(2, 2) = 3e-4;
	o.Height = -0.25;
	const auto back = readAsOlderVersion(o, 1, 2 * sizeof(double));
	ASSERT_TRUE(back);
	EXPECT_EQ(back->landmarkID, 8);
	EXPECT_EQ(back->relPoseCov, o.relPoseCov);
	EXPECT_EQ(back->Height, 0);
}

TEST(Observations, VisualLandmarkOfVersionTwoReadsWithAnUnknownSlopeStd)
{
	// Version 2 is version 3 without the trailing SlopeStd (one double).
	CObservationVisualLandmark o;
	o.landmarkID = 9;
	o.Height = -0.25;
	o.SlopeStd = 0.01;
	const auto back = readAsOlderVersion(o, 2, sizeof(double));
	ASSERT_TRUE(back);
	EXPECT_EQ(back->landmarkID, 9);
	EXPECT_EQ(back->Height, o.Height);
	EXPECT_EQ(back->SlopeStd, 0);
}

TEST(Observations, LandmarkCreatedRoundTrip)
{
	CObservationLandmarkCreated o;
	o.landmarkID = 17;
	o.landmarkPoseInRobot = mrpt::poses::CPose2D(-0.2, 0.01, -0.05);
	o.landmarkPoseInRobotCov(0, 0) = 1e-4;
	o.landmarkPoseInRobotCov(0, 2) = o.landmarkPoseInRobotCov(2, 0) = 2e-6;
	o.NPoints = 80;
	o.NViews = 3;
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << o;
	buf.Seek(0);
	auto back = arch.ReadObject<CObservationLandmarkCreated>();
	ASSERT_TRUE(back);
	EXPECT_EQ(back->landmarkID, 17);
	EXPECT_EQ(back->landmarkPoseInRobot, o.landmarkPoseInRobot);
	EXPECT_EQ(back->landmarkPoseInRobotCov, o.landmarkPoseInRobotCov);
	EXPECT_EQ(back->NPoints, 80u);
	EXPECT_EQ(back->NViews, 3u);
}

TEST(Observations, HeadingChangeRoundTrip)
{
	CObservationHeadingChange o;
	o.timestamp = mrpt::Clock::fromDouble(1700000000.4);
	o.previousTimestamp = mrpt::Clock::fromDouble(1700000000.0);
	o.dphi = -0.0123;
	o.stdDphi = 3e-4;
	o.NMatches = 310;
	o.NInliers = 245;
	o.rmsPx = 0.42;
	o.sensorPoseOnRobot = mrpt::poses::CPose3D(0.1, 0, 0.35, -M_PI / 2, 0, -M_PI / 2);
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << o;
	buf.Seek(0);
	auto back = arch.ReadObject<CObservationHeadingChange>();
	ASSERT_TRUE(back);
	EXPECT_EQ(back->timestamp, o.timestamp);
	EXPECT_EQ(back->previousTimestamp, o.previousTimestamp);
	EXPECT_EQ(back->sensorLabel, "CAMERA_HEADING");
	EXPECT_EQ(back->dphi, o.dphi);
	EXPECT_EQ(back->stdDphi, o.stdDphi);
	EXPECT_EQ(back->NMatches, 310u);
	EXPECT_EQ(back->NInliers, 245u);
	EXPECT_EQ(back->rmsPx, o.rmsPx);
	EXPECT_EQ(back->sensorPoseOnRobot, o.sensorPoseOnRobot);
	EXPECT_EQ(back->exportTxtDataRow(), o.exportTxtDataRow());
	EXPECT_EQ(o.exportTxtHeader(), "since dphi stdDphi NMatches NInliers rmsPx");
	std::ostringstream text;
	o.getDescriptionAsText(text);
	for (const char* f : {"dphi", "NMatches", "NInliers", "rmsPx", "since"})
		EXPECT_NE(text.str().find(f), std::string::npos) << f;
}

TEST(Observations, DescriptionAndExportMentionEveryField)
{
	CObservationVisualLandmark o;
	o.landmarkID = 5;
	o.NPoints = 12;
	std::ostringstream s;
	o.getDescriptionAsText(s);
	for (const char* f : {"landmarkID", "ProjErrRMS", "NPoints", "Slope", "Height"})
		EXPECT_NE(s.str().find(f), std::string::npos) << f;
	EXPECT_TRUE(o.exportTxtSupported());
	EXPECT_EQ(o.exportTxtDataRow().substr(0, 2), "5 ");
}

TEST(Observations, UnknownVersionThrows)
{
	// Write a valid object, then corrupt its version byte.
	CObservationVisualLandmark o;
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << o;
	auto* data = static_cast<uint8_t*>(buf.getRawBufferData());
	const std::string name = "vslam::CObservationVisualLandmark";
	// Layout: one byte (0x80 | name length), the name, the version byte.
	ASSERT_EQ(data[0], 0x80 | name.size());
	const size_t versionPos = 1 + name.size();
	ASSERT_LT(versionPos, buf.getTotalBytesCount());
	data[versionPos] = 99;
	buf.Seek(0);
	EXPECT_ANY_THROW(arch.ReadObject());
}

TEST(Observations, EachKindHasItsOwnDefaultSensorLabel)
{
	// rawlog-edit --export-txt writes one file per sensor label with the
	// first object's header: the two kinds must not share a label.
	EXPECT_EQ(CObservationVisualLandmark().sensorLabel, "CAMERA");
	EXPECT_NE(CObservationLandmarkCreated().sensorLabel, CObservationVisualLandmark().sensorLabel);
	EXPECT_NE(CObservationHeadingChange().sensorLabel, CObservationVisualLandmark().sensorLabel);
	EXPECT_NE(CObservationHeadingChange().sensorLabel, CObservationLandmarkCreated().sensorLabel);
}

// A corrupt label length must not become a 4 GiB allocation (MRPT's own
// string reader would try): every class refuses it with an exception.
TEST(Observations, CorruptSensorLabelLengthThrowsInsteadOfAllocating)
{
	CObservationVisualLandmark visual;
	CObservationLandmarkCreated created;
	CObservationHeadingChange heading;
	for (const mrpt::obs::CObservation* o :
		 std::initializer_list<const mrpt::obs::CObservation*>{&visual, &created, &heading})
	{
		mrpt::io::CMemoryStream buf;
		auto arch = mrpt::serialization::archiveFrom(buf);
		arch << *o;
		auto* data = static_cast<uint8_t*>(buf.getRawBufferData());
		// Layout: 0x80 | name length, name, version, timestamp (8 bytes),
		// then the label's uint32 length.
		const size_t lengthPos = 1 + (data[0] & 0x7F) + 1 + 8;
		ASSERT_LT(lengthPos + 4, buf.getTotalBytesCount());
		uint32_t length = 0;
		std::memcpy(&length, data + lengthPos, 4);
		EXPECT_EQ(length, o->sensorLabel.size());
		const uint32_t corrupt = 0xF0000000u;
		std::memcpy(data + lengthPos, &corrupt, 4);
		buf.Seek(0);
		try
		{
			arch.ReadObject();
			ADD_FAILURE() << "no exception";
		}
		catch (const std::exception& e)
		{
			EXPECT_NE(std::string(e.what()).find("sensor label of 4026531840 bytes"), std::string::npos)
				<< e.what();
		}
	}
}

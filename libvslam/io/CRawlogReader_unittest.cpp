#include <gtest/gtest.h>
#include <libvslam/core/InputError.h>
#include <libvslam/io/CCheckedGzInputStream.h>
#include <libvslam/io/CRawlogReader.h>
#include <libvslam/obs/CObservationVisualLandmark.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <tests/support/TempDir.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace vslam;
using vslam::testing::TempDir;

namespace
{
mrpt::Clock::time_point at(double s) { return mrpt::Clock::fromDouble(1.7e9 + s); }

CObservationVisualLandmark::Ptr visual(int64_t id, double t)
{
	auto o = CObservationVisualLandmark::Create();
	o->landmarkID = id;
	o->timestamp = at(t);
	o->NPoints = 30;
	return o;
}

/** Format #1: n (action, sensory frame) pairs. */
void writeFormat1(const std::string& file, int n, double nanAt = -1, double badDx = std::nan(""))
{
	mrpt::io::CFileGZOutputStream out(file);
	auto arch = mrpt::serialization::archiveFrom(out);
	for (int i = 0; i < n; i++)
	{
		mrpt::obs::CActionCollection acts;
		mrpt::obs::CActionRobotMovement2D mv;
		const double dx = i == nanAt ? badDx : 0.1;
		mv.computeFromOdometry(mrpt::poses::CPose2D(dx, 0, 0.01), {});
		mv.timestamp = at(i);
		acts.insert(mv);
		mrpt::obs::CSensoryFrame sf;
		if (i % 2 == 0) sf.insert(visual(i, i));
		arch << acts << sf;
	}
}

std::string readAll(const std::string& file)
{
	std::ifstream in(file, std::ios::binary);
	return {std::istreambuf_iterator<char>(in), {}};
}

void writeBytes(const std::string& file, const std::string& bytes)
{
	std::ofstream out(file, std::ios::binary);
	out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

/** The uncompressed content of a gzip file. */
std::string inflate(const std::string& file)
{
	CCheckedGzInputStream in(file);
	std::string data(1 << 20, '\0');
	data.resize(in.Read(data.data(), data.size()));
	return data;
}

std::string errorOf(const std::string& file)
{
	try
	{
		CRawlogReader r(file);
		RawlogStep s;
		while (r.next(s))
		{
		}
	}
	catch (const InputError& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(CRawlogReader, ReadsActionSensoryFramePairs)
{
	TempDir dir;
	const auto file = dir.file("a.rawlog");
	writeFormat1(file, 10);
	CRawlogReader r(file);
	RawlogStep s;
	size_t n = 0;
	while (r.next(s))
	{
		ASSERT_TRUE(s.action);
		ASSERT_TRUE(s.sf);
		EXPECT_EQ(s.entry, 2 * n);
		EXPECT_EQ(s.sf->size(), n % 2 == 0 ? 1u : 0u);
		EXPECT_EQ(s.timestamp, at(n));
		n++;
	}
	EXPECT_EQ(n, 10u);
	EXPECT_EQ(r.actionFrameSteps(), 10u);
	EXPECT_EQ(CRawlogReader::imagesDirectory("/x/y/a.rawlog"), "/x/y/a_Images");
	EXPECT_EQ(CRawlogReader::imagesDirectory("b.rawlog.gz"), "b_Images");
}

TEST(CRawlogReader, ReadsObservationRawlogsWithOdometryDifferencesAndGrouping)
{
	TempDir dir;
	const auto file = dir.file("b.rawlog");
	{
		mrpt::io::CFileGZOutputStream out(file);
		auto arch = mrpt::serialization::archiveFrom(out);
		mrpt::poses::CPose2D odo(1, 2, 0.5);
		for (int i = 0; i < 5; i++)
		{
			auto o = mrpt::obs::CObservationOdometry::Create();
			o->odometry = odo;
			o->timestamp = at(i);
			arch << *o;
			odo = odo + mrpt::poses::CPose2D(0.2, 0, 0.1);
			// Two measurements of one image, then one of the next.
			arch << *visual(10 * i, i + 0.5) << *visual(10 * i + 1, i + 0.5);
		}
		arch << *visual(99, 9);
	}
	CRawlogReader r(file);
	RawlogStep s;
	std::vector<RawlogStep> steps;
	while (r.next(s)) steps.push_back(s);
	ASSERT_EQ(steps.size(), 11u);
	// The first odometry reading only sets the reference.
	const auto inc0 = steps[0].action->getBestMovementEstimation()->poseChange->getMeanVal();
	EXPECT_NEAR(inc0.norm(), 0, 1e-12);
	const auto inc1 = steps[2].action->getBestMovementEstimation()->poseChange->getMeanVal();
	EXPECT_NEAR(inc1.x(), 0.2, 1e-9);
	EXPECT_NEAR(inc1.phi(), 0.1, 1e-9);
	EXPECT_EQ(steps[1].sf->size(), 2u);  // grouped by timestamp
	EXPECT_EQ(steps[10].sf->size(), 1u);
	EXPECT_EQ(r.observationSteps(), 11u);
}

TEST(CRawlogReader, ReadsPlainUncompressedRawlogs)
{
	TempDir dir;
	writeFormat1(dir.file("gz.rawlog"), 6);
	writeBytes(dir.file("plain.rawlog"), inflate(dir.file("gz.rawlog")));
	CRawlogReader r(dir.file("plain.rawlog"));
	RawlogStep s;
	size_t n = 0;
	while (r.next(s)) n++;
	EXPECT_EQ(n, 6u);
}

TEST(CRawlogReader, MissingFileNamesTheFile)
{
	const std::string e = errorOf("/nonexistent/dir/x.rawlog");
	EXPECT_NE(e.find("/nonexistent/dir/x.rawlog"), std::string::npos) << e;
}

TEST(CRawlogReader, TruncatedRawlogsAreErrorsNotShorterRuns)
{
	TempDir dir;
	writeFormat1(dir.file("full.rawlog"), 40);
	const std::string gz = readAll(dir.file("full.rawlog"));
	const std::string plain = inflate(dir.file("full.rawlog"));
	// A plain file cut exactly between two objects is a valid shorter
	// rawlog and cannot be told apart; these cuts fall 7 bytes into an
	// object (the smallest object here is 31 bytes).
	for (const double frac : {0.0, 0.3, 0.5, 0.77, 0.93})
	{
		writeBytes(dir.file("t.rawlog"), gz.substr(0, size_t(gz.size() * frac) + 7));
		EXPECT_NE(errorOf(dir.file("t.rawlog")), "") << "gzip cut at " << frac;
		writeBytes(dir.file("p.rawlog"), plain.substr(0, size_t(plain.size() * frac) + 7));
		const std::string e = errorOf(dir.file("p.rawlog"));
		EXPECT_NE(e.find("entry"), std::string::npos) << "plain cut at " << frac << ": " << e;
	}
}

TEST(CRawlogReader, GzipCutBetweenObjectsIsStillTruncated)
{
	TempDir dir;
	writeFormat1(dir.file("full.rawlog"), 40);
	const std::string plain = inflate(dir.file("full.rawlog"));
	// Re-compress only the first 20 pairs: a complete gzip stream...
	writeFormat1(dir.file("half.rawlog"), 20);
	const std::string halfPlain = inflate(dir.file("half.rawlog"));
	ASSERT_EQ(plain.substr(0, halfPlain.size()), halfPlain);
	EXPECT_EQ(errorOf(dir.file("half.rawlog")), "");
	// ...while the full file's gzip stream cut short is an error wherever
	// the cut falls.
	const std::string gz = readAll(dir.file("full.rawlog"));
	for (size_t cut = gz.size() - 8; cut < gz.size(); cut++)
	{
		writeBytes(dir.file("t.rawlog"), gz.substr(0, cut));
		EXPECT_NE(errorOf(dir.file("t.rawlog")).find("truncated"), std::string::npos) << cut;
	}
}

TEST(CRawlogReader, CorruptBytesAreErrors)
{
	TempDir dir;
	writeFormat1(dir.file("full.rawlog"), 40);
	std::string gz = readAll(dir.file("full.rawlog"));
	for (size_t i = gz.size() / 2; i < gz.size() / 2 + 16; i++) gz[i] ^= 0x5a;
	writeBytes(dir.file("c.rawlog"), gz);
	const std::string e = errorOf(dir.file("c.rawlog"));
	EXPECT_NE(e.find("c.rawlog"), std::string::npos) << e;
	EXPECT_NE(e.find("corrupt"), std::string::npos) << e;
}

// Found by fuzz_rawlog: a corrupt element count made MRPT allocate a
// sensory frame of 2^31 observations (gigabytes, then a hang or the OOM killer).
TEST(CRawlogReader, ImpossibleElementCountsAreErrorsNotAllocations)
{
	TempDir dir;
	writeFormat1(dir.file("full.rawlog"), 6);
	const std::string plain = inflate(dir.file("full.rawlog"));
	// Entries alternate action, frame: the third of each is entry 4 / 5.
	for (const auto& [name, entry] : {std::pair<std::string, std::string>{"mrpt::obs::CActionCollection", "entry 4"},
			 {"mrpt::obs::CSensoryFrame", "entry 5"}})
	{
		std::string bytes = plain;
		// The third occurrence: entries before it are read normally.
		size_t pos = 0;
		for (int k = 0; k < 3; k++) pos = bytes.find(name, pos + (k ? 1 : 0));
		ASSERT_NE(pos, std::string::npos);
		const size_t countAt = pos + name.size() + 1;  // after the version byte
		for (size_t i = 0; i < 4; i++) bytes[countAt + i] = i == 3 ? '\x7f' : '\xff';
		writeBytes(dir.file("plain.rawlog"), bytes);
		{
			mrpt::io::CFileGZOutputStream gz(dir.file("gz.rawlog"));
			gz.Write(bytes.data(), bytes.size());
		}
		for (const char* file : {"plain.rawlog", "gz.rawlog"})
		{
			const std::string e = errorOf(dir.file(file));
			EXPECT_NE(e.find(file), std::string::npos) << e;
			EXPECT_NE(e.find(entry), std::string::npos) << e;
			EXPECT_NE(e.find("claims 2147483647 elements"), std::string::npos) << e;
		}
	}
}

TEST(CCheckedGzInputStream, PeekedBytesAreReadAgain)
{
	TempDir dir;
	writeBytes(dir.file("p.bin"), "abcdef");
	CCheckedGzInputStream in(dir.file("p.bin"));
	EXPECT_EQ(in.peek(3), "abc");
	EXPECT_EQ(in.peek(10), "abcdef");
	EXPECT_EQ(in.remainingBytesBound(), 6u);
	char buf[4] = {};
	ASSERT_EQ(in.Read(buf, 2), 2u);
	EXPECT_EQ(std::string(buf, 2), "ab");
	EXPECT_EQ(in.getPosition(), 2u);
	EXPECT_EQ(in.remainingBytesBound(), 4u);
	EXPECT_EQ(in.peek(1), "c");
	ASSERT_EQ(in.Read(buf, 4), 4u);
	EXPECT_EQ(std::string(buf, 4), "cdef");
	EXPECT_EQ(in.Read(buf, 4), 0u);
	EXPECT_EQ(in.peek(4), "");
}

TEST(CRawlogReader, OdometryIncrementsBeyondAnyRobotAreCorrupt)
{
	TempDir dir;
	writeFormat1(dir.file("huge.rawlog"), 10, 4, 1e9);
	const std::string e = errorOf(dir.file("huge.rawlog"));
	EXPECT_NE(e.find("entry 8"), std::string::npos) << e;
	EXPECT_NE(e.find("beyond any robot's motion"), std::string::npos) << e;
}

TEST(CRawlogReader, UnknownClassesAreNamed)
{
	TempDir dir;
	writeFormat1(dir.file("full.rawlog"), 4);
	std::string plain = inflate(dir.file("full.rawlog"));
	const std::string name = "vslam::CObservationVisualLandmark";
	const auto pos = plain.find(name);
	ASSERT_NE(pos, std::string::npos);
	plain.replace(pos, name.size(), "vslam::CObservationVisualLandmarX");
	writeBytes(dir.file("u.rawlog"), plain);
	const std::string e = errorOf(dir.file("u.rawlog"));
	EXPECT_NE(e.find("CObservationVisualLandmarX"), std::string::npos) << e;
	EXPECT_NE(e.find("entry 1"), std::string::npos) << e;
}

TEST(CRawlogReader, NonFiniteOdometryNamesTheEntry)
{
	TempDir dir;
	writeFormat1(dir.file("n.rawlog"), 10, 4);
	const std::string e = errorOf(dir.file("n.rawlog"));
	EXPECT_NE(e.find("entry 8"), std::string::npos) << e;
	EXPECT_NE(e.find("not finite"), std::string::npos) << e;
}

TEST(CRawlogReader, ReadsMrptsKfSlamDemoRawlog)
{
	const std::string file = "/usr/share/mrpt/datasets/kf-slam_demo.rawlog";
	if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " absent (package mrpt-common)";
	// A leading sensory frame (no action), 249 pairs, a trailing action.
	// MRPT's own reader drops the first and the last; we keep them.
	CRawlogReader r(file);
	RawlogStep s;
	size_t n = 0, withRb = 0, withAction = 0;
	while (r.next(s))
	{
		n++;
		withRb += s.sf->getObservationByClass<mrpt::obs::CObservationBearingRange>() != nullptr;
		withAction += s.action != nullptr;
	}
	EXPECT_EQ(r.objectsRead(), 500u);
	EXPECT_EQ(n, 251u);
	EXPECT_EQ(withRb, 250u);
	EXPECT_EQ(withAction, 250u);
}

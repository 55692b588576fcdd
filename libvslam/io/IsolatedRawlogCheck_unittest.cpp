#include <gtest/gtest.h>
#include <libvslam/core/InputError.h>
#include <libvslam/io/CRawlogReader.h>
#include <libvslam/io/IsolatedRawlogCheck.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <tests/support/TempDir.h>

#include <fstream>

using namespace vslam;
using vslam::testing::TempDir;

namespace
{
/** Format #1, n (action, empty sensory frame) pairs; the action at pair
 * `badPair` claims a particle motion model of `particles` samples, which
 * MRPT's deserializer draws while reading it. */
void writeRawlog(const std::string& file, int n, int badPair = -1, uint32_t particles = 0)
{
	mrpt::io::CFileGZOutputStream out(file);
	auto arch = mrpt::serialization::archiveFrom(out);
	for (int i = 0; i < n; i++)
	{
		mrpt::obs::CActionCollection acts;
		mrpt::obs::CActionRobotMovement2D mv;
		mv.computeFromOdometry(mrpt::poses::CPose2D(0.1, 0, 0.01), {});
		if (i == badPair)
		{
			mv.motionModelConfiguration.modelSelection = mrpt::obs::CActionRobotMovement2D::mmThrun;
			mv.motionModelConfiguration.thrunModel.nParticlesCount = particles;
		}
		acts.insert(mv);
		arch << acts << mrpt::obs::CSensoryFrame();
	}
}

/** Reads the whole file as the apps do; returns the error, or "" and the
 * number of steps read. */
std::string readToTheEnd(const std::string& file, const TIsolatedReadOptions& limits, size_t* steps = nullptr)
{
	try
	{
		CRawlogReader reader(file, limits);
		RawlogStep step;
		size_t n = 0;
		while (reader.next(step)) n++;
		if (steps) *steps = n;
	}
	catch (const InputError& e)
	{
		return e.what();
	}
	return "";
}

std::string testData(const std::string& name)
{
	return std::string(VSLAM_SOURCE_DIR) + "/libvslam/io/testdata/" + name;
}
}  // namespace

TEST(IsolatedRawlogCheck, ACleanRawlogIsReadToTheEnd)
{
	TempDir dir;
	writeRawlog(dir.file("clean.rawlog"), 20);
	EXPECT_FALSE(findUnreadableEntry(dir.file("clean.rawlog")).has_value());
	size_t steps = 0;
	EXPECT_EQ(readToTheEnd(dir.file("clean.rawlog"), {}, &steps), "");
	EXPECT_EQ(steps, 20u);
}

TEST(IsolatedRawlogCheck, OrdinaryReadErrorsAreLeftToTheReader)
{
	// A truncated file: the child stops at the error like the reader would,
	// and the reader's own message (which names the truncation) is the one
	// the user sees.
	TempDir dir;
	writeRawlog(dir.file("full.rawlog"), 20);
	std::string bytes;
	{
		std::ifstream in(dir.file("full.rawlog"), std::ios::binary);
		bytes.assign(std::istreambuf_iterator<char>(in), {});
	}
	std::ofstream(dir.file("cut.rawlog"), std::ios::binary).write(bytes.data(), std::streamsize(bytes.size() / 2));
	EXPECT_FALSE(findUnreadableEntry(dir.file("cut.rawlog")).has_value());
	const std::string e = readToTheEnd(dir.file("cut.rawlog"), {});
	EXPECT_NE(e.find("truncated"), std::string::npos) << e;
}

// Found by fuzz_rawlog: bytes on which MRPT 2.5.8's own deserializers
// dereference a null pointer. Before the isolated check, `vslam` died of
// SIGSEGV on them; now the reader names the entry and stops there.
TEST(IsolatedRawlogCheck, SegfaultsInsideMrptsDeserializersAreErrorsNamingTheEntry)
{
	for (const auto& [name, entry] : {std::pair<std::string, size_t>{"segv_in_mrpt_deserializer_1.rawlog", 6},
			 {"segv_in_mrpt_deserializer_2.rawlog", 0}})
	{
		const auto bad = findUnreadableEntry(testData(name));
		ASSERT_TRUE(bad.has_value()) << name;
		EXPECT_EQ(bad->entry, entry) << name;
		EXPECT_NE(bad->why.find("Segmentation fault"), std::string::npos) << bad->why;
		size_t steps = 0;
		const std::string e = readToTheEnd(testData(name), {}, &steps);
		EXPECT_NE(e.find(name), std::string::npos) << e;
		EXPECT_NE(e.find("entry " + std::to_string(entry) + ":"), std::string::npos) << e;
		EXPECT_NE(e.find("corrupt data"), std::string::npos) << e;
	}
}

TEST(IsolatedRawlogCheck, ACorruptCountInsideAnObjectIsStoppedByTheMemoryLimit)
{
	// Two billion particles: MRPT would allocate and draw them for minutes.
	TempDir dir;
	writeRawlog(dir.file("huge.rawlog"), 6, 3, 2'000'000'000u);
	TIsolatedReadOptions limits;
	limits.maxBytesPerEntry = uint64_t(256) << 20;
	const auto bad = findUnreadableEntry(dir.file("huge.rawlog"), limits);
	ASSERT_TRUE(bad.has_value());
	EXPECT_EQ(bad->entry, 6u);  // the fourth action
	EXPECT_NE(bad->why.find("256 MiB"), std::string::npos) << bad->why;
	size_t steps = 0;
	const std::string e = readToTheEnd(dir.file("huge.rawlog"), limits, &steps);
	EXPECT_NE(e.find("entry 6:"), std::string::npos) << e;
}

TEST(IsolatedRawlogCheck, AnEntryThatDoesNotEndIsStoppedByTheTimeLimit)
{
	TempDir dir;
	writeRawlog(dir.file("slow.rawlog"), 6, 2, 2'000'000'000u);
	TIsolatedReadOptions limits;
	limits.maxSecondsPerEntry = 0.5;
	limits.maxBytesPerEntry = uint64_t(64) << 30;
	const auto bad = findUnreadableEntry(dir.file("slow.rawlog"), limits);
	ASSERT_TRUE(bad.has_value());
	EXPECT_EQ(bad->entry, 4u);
	EXPECT_NE(bad->why.find("did not end within"), std::string::npos) << bad->why;
}

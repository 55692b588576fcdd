#include <gtest/gtest.h>
#include <libvslam/core/OutputError.h>
#include <libvslam/io/COutputFile.h>
#include <libvslam/io/CPathFileWriter.h>
#include <tests/support/RunCommand.h>
#include <tests/support/TempDir.h>

#include <filesystem>
#include <fstream>

using namespace vslam;
using vslam::testing::readFile;
namespace fs = std::filesystem;

namespace
{
/** The message of the OutputError `f` throws, or "" if it throws none. */
template <class F>
std::string outputErrorOf(F&& f)
{
	try
	{
		f();
	}
	catch (const OutputError& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(COutputFile, AtomicFileAppearsWholeOnlyAtCommit)
{
	vslam::testing::TempDir dir;
	const std::string file = dir.file("summary.yaml");
	std::ofstream(file) << "old\n";
	{
		COutputFile out(file, COutputFile::Mode::Atomic);
		out.write("new ");
		out.print("%d\n", 42);
		out.flush();
		EXPECT_EQ(readFile(file), "old\n");  // the old file until the commit
		out.commit();
	}
	EXPECT_EQ(readFile(file), "new 42\n");
	EXPECT_FALSE(fs::exists(file + ".tmp"));
}

TEST(COutputFile, AnAtomicFileNotCommittedLeavesTheOldOneAndNoTemporary)
{
	vslam::testing::TempDir dir;
	const std::string file = dir.file("final_map.txt");
	std::ofstream(file) << "old\n";
	{
		COutputFile out(file, COutputFile::Mode::Atomic);
		out.write("half a ");
	}
	EXPECT_EQ(readFile(file), "old\n");
	EXPECT_FALSE(fs::exists(file + ".tmp"));
}

TEST(COutputFile, AFullDeviceIsAnOutputErrorNamingTheFileAndTheReason)
{
	if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
	// /dev/full accepts the open and fails every write with ENOSPC.
	const std::string streamed = outputErrorOf([] {
		COutputFile out("/dev/full", COutputFile::Mode::Streamed);
		out.write(std::string(10, 'x'));
		out.flush();
	});
	EXPECT_NE(streamed.find("'/dev/full'"), std::string::npos) << streamed;
	EXPECT_NE(streamed.find("No space left on device"), std::string::npos) << streamed;
	const std::string path = outputErrorOf([] {
		CPathFileWriter w("/dev/full", CPathFileWriter::Format::Tum);
	});
	EXPECT_NE(path.find("No space left on device"), std::string::npos) << path;
}

TEST(COutputFile, AnUnwritableFolderIsAnOutputErrorNamingTheFile)
{
	const std::string message = outputErrorOf([] {
		COutputFile out("/nonexistent-folder/x.txt", COutputFile::Mode::Atomic);
	});
	EXPECT_NE(message.find("cannot create output file '/nonexistent-folder/x.txt'"), std::string::npos) << message;
	EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
}

#include <gtest/gtest.h>
#include <libvslam/config/StrictRead.h>
#include <mrpt/config/CConfigFileMemory.h>

using namespace vslam;
using namespace vslam::config;

namespace
{
std::string errorOf(const std::function<void()>& f)
{
	try
	{
		f();
	}
	catch (const ConfigError& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(StrictRead, ReadsValidValuesAndKeepsDefaultsForAbsentKeys)
{
	mrpt::config::CConfigFileMemory c(
		"[s]\na = 0.25 // a comment\nb = 12\nc = yes\nd = deg\ne = 90\n");
	EXPECT_DOUBLE_EQ(readDouble(c, "s", "a", 9), 0.25);
	EXPECT_DOUBLE_EQ(readDouble(c, "s", "missing", 9), 9);
	EXPECT_EQ(readInt(c, "s", "b", 0), 12);
	EXPECT_TRUE(readBool(c, "s", "c", false));
	EXPECT_EQ(readString(c, "s", "d", ""), "deg");
	EXPECT_NEAR(readDegreesAsRadians(c, "s", "e", 0), M_PI / 2, 1e-12);
	EXPECT_EQ(readChoice(c, "s", "d", 0, {"rad", "deg"}), 1u);
	EXPECT_EQ(readWord(c, "s", "d", "rad", {"rad", "deg"}), "deg");
	EXPECT_EQ(readWord(c, "s", "absent", "rad", {"rad", "deg"}), "rad");
	EXPECT_THROW(readWord(c, "s", "absent", "grad", {"rad", "deg"}), std::logic_error);
}

TEST(StrictRead, AnEmptyValueFollowedByACommentIsEmpty)
{
	// The form MRPT's write(section, key, "", ..., comment) produces.
	mrpt::config::CConfigFileMemory c("[s]\nfile =   // where the data is\nn = // count\n");
	EXPECT_EQ(readString(c, "s", "file", "default"), "");
	EXPECT_NE(errorOf([&] { readInt(c, "s", "n", 3); }), "");
}

TEST(StrictRead, UnparsableValuesNameSectionAndKey)
{
	mrpt::config::CConfigFileMemory c(
		"[motion]\nsigma_T = abc\nx = 0.3 # hash\nn = 2.5\nb = maybe\n"
		"k = nan\n");
	const std::string e1 = errorOf([&] { readDouble(c, "motion", "sigma_T", 0); });
	EXPECT_NE(e1.find("[motion] sigma_T"), std::string::npos) << e1;
	EXPECT_NE(e1.find("'abc'"), std::string::npos) << e1;
	EXPECT_NE(errorOf([&] { readDouble(c, "motion", "x", 0); }).find("'//'"),
			  std::string::npos);
	EXPECT_NE(errorOf([&] { readInt(c, "motion", "n", 0); }), "");
	EXPECT_NE(errorOf([&] { readBool(c, "motion", "b", false); }), "");
	EXPECT_NE(errorOf([&] { readDouble(c, "motion", "k", 0); }), "");
}

TEST(StrictRead, OutOfRangeValuesSayTheAllowedRange)
{
	mrpt::config::CConfigFileMemory c("[pf]\nBETA = 1.5\nN = 0\nch = foo\n");
	const std::string e =
		errorOf([&] { readDouble(c, "pf", "BETA", 0.5, Range::closed(0, 1)); });
	EXPECT_NE(e.find("out of range"), std::string::npos) << e;
	EXPECT_NE(e.find("[0, 1]"), std::string::npos) << e;
	EXPECT_NE(errorOf([&] { readInt(c, "pf", "N", 1, Range::closed(1, 1e6)); }), "");
	const std::string e3 =
		errorOf([&] { readChoice(c, "pf", "ch", 0, {"joint", "sequential"}); });
	EXPECT_NE(e3.find("joint, sequential"), std::string::npos) << e3;
	EXPECT_NE(errorOf([&] { readWord(c, "pf", "ch", "joint", {"joint", "sequential"}); }).find("ch"), std::string::npos);
}

TEST(StrictRead, HexadecimalNumbersAreErrorsNotSixteen)
{
	mrpt::config::CConfigFileMemory c("[s]\nd = 0x10\ni = 0x10\nf = 0X1p3\n");
	EXPECT_NE(errorOf([&] { readDouble(c, "s", "d", 0); }).find("[s] d = '0x10': not a decimal number"),
		std::string::npos);
	EXPECT_NE(errorOf([&] { readInt(c, "s", "i", 0); }), "");
	EXPECT_NE(errorOf([&] { readDouble(c, "s", "f", 0); }), "");
}

TEST(StrictRead, TheRecorderListsEveryNumericKeyReadWithItsRange)
{
	mrpt::config::CConfigFileMemory c("[s]\na = 2\n");
	NumericKeyRecorder recorder;
	readDouble(c, "s", "a", 1, Range::closed(0, 5));
	readInt(c, "s", "absent", 3, Range::positive());
	readDegreesAsRadians(c, "s", "angle_deg", M_PI / 2, Range::closed(0, 180));
	readDouble(c, "s", "a", 1, Range::closed(0, 5));  // read twice, listed once
	ASSERT_EQ(recorder.keys().size(), 3u);
	EXPECT_EQ(recorder.keys()[0].key, "a");
	EXPECT_EQ(recorder.keys()[0].range.hi, 5);
	EXPECT_EQ(recorder.keys()[1].key, "absent");
	EXPECT_TRUE(recorder.keys()[1].integer);
	EXPECT_EQ(recorder.keys()[1].defaultValue, 3);
	EXPECT_NEAR(recorder.keys()[2].defaultValue, 90, 1e-9);  // in the key's own unit
	EXPECT_EQ(recorder.keys()[2].range.hi, 180);
}

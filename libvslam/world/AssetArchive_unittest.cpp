/** Assets inside zip archives: a member is found through the archive's
 * path, read whole, decoded as an image, and its folder unpacked for
 * loaders that read from disk (and removed afterwards); a missing member,
 * a corrupt archive and a plain file behave as they should. */
#include <gtest/gtest.h>
#include <libvslam/core/InputError.h>
#include <libvslam/world/AssetArchive.h>
#include <opencv2/imgcodecs.hpp>
#include <tests/support/TempDir.h>
#include <zip.h>

#include <fstream>

using namespace vslam::world;
namespace fs = std::filesystem;

namespace
{
/** A .sh3f-like archive with a model folder: an image and a text file. */
std::string makeArchive(const fs::path& dir)
{
	const std::string file = (dir / "lib.sh3f").string();
	int error = 0;
	zip_t* z = zip_open(file.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
	std::vector<unsigned char> png;
	cv::imencode(".png", cv::Mat(20, 30, CV_8UC3, cv::Scalar(10, 20, 30)), png);
	static std::vector<unsigned char> image;
	image = png;
	static const std::string text = "mtllib chair.mtl\n";
	zip_file_add(z, "chair/wood.png", zip_source_buffer(z, image.data(), image.size(), 0), 0);
	zip_file_add(z, "chair/chair.obj", zip_source_buffer(z, text.data(), text.size(), 0), 0);
	zip_file_add(z, "table/table.obj", zip_source_buffer(z, text.data(), text.size(), 0), 0);
	zip_close(z);
	return file;
}
}  // namespace

TEST(AssetArchive, MembersAreFoundReadAndDecoded)
{
	vslam::testing::TempDir dir;
	const std::string archive = makeArchive(dir.path());
	const auto at = locateAsset(archive + "/chair/wood.png");
	ASSERT_TRUE(at.has_value());
	EXPECT_EQ(at->archive, archive);
	EXPECT_EQ(at->member, "chair/wood.png");
	const cv::Mat img = readAssetImage(*at);
	EXPECT_EQ(img.cols, 30);
	EXPECT_EQ(img.at<cv::Vec3b>(5, 5)[2], 30);
	EXPECT_FALSE(locateAsset(archive + "/chair/missing.png").has_value());
	EXPECT_FALSE(locateAsset((dir.path() / "nothing.jpg").string()).has_value());
	EXPECT_THROW(readAssetImage({archive, "chair/chair.obj"}), vslam::InputError);  // not an image

	std::ofstream(dir.path() / "plain.txt") << "hello";
	const auto plain = locateAsset((dir.path() / "plain.txt").string());
	ASSERT_TRUE(plain.has_value());
	EXPECT_TRUE(plain->archive.empty());
	EXPECT_EQ(readAsset(*plain).size(), 5u);
}

TEST(AssetArchive, AModelsFolderIsUnpackedAndRemovedAfterwards)
{
	vslam::testing::TempDir dir;
	const std::string archive = makeArchive(dir.path());
	fs::path unpacked;
	{
		const ExtractedAsset model({archive, "chair/chair.obj"});
		unpacked = fs::path(model.path()).parent_path();
		EXPECT_TRUE(fs::is_regular_file(model.path()));
		EXPECT_TRUE(fs::is_regular_file(unpacked / "wood.png"));  // its texture beside it
		EXPECT_FALSE(fs::exists(unpacked.parent_path() / "table"));  // only its folder
	}
	EXPECT_FALSE(fs::exists(unpacked));
}

TEST(AssetArchive, ACorruptArchiveIsAnErrorNamingIt)
{
	vslam::testing::TempDir dir;
	const fs::path bad = dir.path() / "broken.jar";
	std::ofstream(bad) << "not a zip file at all";
	try
	{
		locateAsset((bad / "textures/wood.jpg").string());
		FAIL() << "no error";
	}
	catch (const vslam::InputError& e)
	{
		EXPECT_NE(std::string(e.what()).find("broken.jar"), std::string::npos) << e.what();
	}
}

#pragma once
/** \file AssetArchive.h
 * Textures and furniture models as Debian ships them: a plain file, or a
 * member of a zip archive on the way (Sweet Home 3D keeps its textures in
 * sweethome3d.jar and its furniture in .sh3f files), so world files name
 * package files directly and nothing is unpacked at set-up:
 *
 *     sweethome3d/sweethome3d.jar/com/eteks/sweethome3d/io/resources/textures/roughcast.jpg
 *     sweethome3d/furniture/KatorLegaz.sh3f/katorlegaz/full-bookcase/full-bookcase.obj
 *
 * A path component ending in .jar, .sh3f or .zip that is a regular file is
 * read as an archive and the rest of the path as the member's name.
 */
#include <opencv2/core.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vslam::world
{
struct AssetLocation
{
	std::string archive;  //!< the zip file, or empty for a plain file
	std::string member;  //!< name inside the archive, or the plain file
};

/** Where `path` is, or nullopt if it names neither a plain file nor an
 * existing archive member. */
std::optional<AssetLocation> locateAsset(const std::string& path);

/** The bytes of an asset; InputError naming it if it cannot be read. */
std::vector<unsigned char> readAsset(const AssetLocation& at);

/** An asset decoded as a BGR image; InputError if it is not one. */
cv::Mat readAssetImage(const AssetLocation& at);

/** The folder of an archive member (the model, its materials and
 * textures) unpacked into a private temporary folder, removed when this
 * object goes; a plain file is used where it is. For loaders that only
 * read from disk (assimp follows an OBJ's relative paths). */
class ExtractedAsset
{
   public:
	explicit ExtractedAsset(const AssetLocation& at);
	~ExtractedAsset();
	ExtractedAsset(const ExtractedAsset&) = delete;
	ExtractedAsset& operator=(const ExtractedAsset&) = delete;

	/** The file on disk. */
	const std::string& path() const { return m_path; }

   private:
	std::filesystem::path m_tempDir;
	std::string m_path;
};
}  // namespace vslam::world

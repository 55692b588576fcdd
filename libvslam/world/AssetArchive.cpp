#include <libvslam/core/InputError.h>
#include <libvslam/world/AssetArchive.h>
#include <opencv2/imgcodecs.hpp>
#include <zip.h>

#include <cstdlib>
#include <fstream>
#include <memory>

namespace vslam::world
{
namespace
{
namespace fs = std::filesystem;

bool isArchiveName(const fs::path& p)
{
	const std::string ext = p.extension().string();
	return ext == ".jar" || ext == ".sh3f" || ext == ".zip";
}

struct ZipCloser
{
	void operator()(zip_t* z) const { zip_discard(z); }
};
using ZipHandle = std::unique_ptr<zip_t, ZipCloser>;

ZipHandle openArchive(const std::string& file)
{
	int error = 0;
	zip_t* z = zip_open(file.c_str(), ZIP_RDONLY, &error);
	if (!z)
	{
		zip_error_t e;
		zip_error_init_with_code(&e, error);
		const std::string why = zip_error_strerror(&e);
		zip_error_fini(&e);
		throw InputError("cannot read archive '" + file + "': " + why);
	}
	return ZipHandle(z);
}

std::vector<unsigned char> readMember(zip_t* z, const std::string& archive, zip_int64_t index)
{
	const std::string name = zip_get_name(z, static_cast<zip_uint64_t>(index), 0);
	zip_stat_t st;
	zip_stat_init(&st);
	if (zip_stat_index(z, static_cast<zip_uint64_t>(index), 0, &st) != 0 || !(st.valid & ZIP_STAT_SIZE))
		throw InputError("archive '" + archive + "': cannot read the size of '" + name + "'");
	if (st.size > (1u << 30)) throw InputError("archive '" + archive + "': '" + name + "' is over 1 GiB");
	std::vector<unsigned char> bytes(static_cast<size_t>(st.size));
	zip_file_t* f = zip_fopen_index(z, static_cast<zip_uint64_t>(index), 0);
	if (!f) throw InputError("archive '" + archive + "': cannot open '" + name + "'");
	const zip_int64_t got = bytes.empty() ? 0 : zip_fread(f, bytes.data(), bytes.size());
	zip_fclose(f);
	if (got != static_cast<zip_int64_t>(bytes.size()))
		throw InputError("archive '" + archive + "': '" + name + "' is truncated or corrupt");
	return bytes;
}

void writeFile(const fs::path& file, const std::vector<unsigned char>& bytes)
{
	fs::create_directories(file.parent_path());
	std::ofstream out(file, std::ios::binary);
	out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
	out.close();
	if (!out) throw InputError("cannot write '" + file.string() + "' (disk full?)");
}

fs::path makeTempDir()
{
	std::string pattern = (fs::temp_directory_path() / "vslam-asset-XXXXXX").string();
	if (!mkdtemp(pattern.data())) throw InputError("cannot create a temporary folder under " + fs::temp_directory_path().string());
	return pattern;
}
}  // namespace

std::optional<AssetLocation> locateAsset(const std::string& path)
{
	std::error_code ec;
	if (fs::is_regular_file(path, ec) && !isArchiveName(path)) return AssetLocation{"", path};
	// Walk down the path: the first component that is an archive file.
	fs::path prefix;
	const fs::path full(path);
	for (auto it = full.begin(); it != full.end(); ++it)
	{
		prefix /= *it;
		if (!isArchiveName(prefix) || !fs::is_regular_file(prefix, ec)) continue;
		fs::path member;
		for (auto rest = std::next(it); rest != full.end(); ++rest) member /= *rest;
		if (member.empty()) return std::nullopt;
		ZipHandle z = openArchive(prefix.string());
		if (zip_name_locate(z.get(), member.generic_string().c_str(), 0) < 0) return std::nullopt;
		return AssetLocation{prefix.string(), member.generic_string()};
	}
	return std::nullopt;
}

std::vector<unsigned char> readAsset(const AssetLocation& at)
{
	if (at.archive.empty())
	{
		std::ifstream in(at.member, std::ios::binary);
		if (!in) throw InputError("cannot read '" + at.member + "'");
		return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), {});
	}
	ZipHandle z = openArchive(at.archive);
	const zip_int64_t index = zip_name_locate(z.get(), at.member.c_str(), 0);
	if (index < 0) throw InputError("archive '" + at.archive + "' has no member '" + at.member + "'");
	return readMember(z.get(), at.archive, index);
}

cv::Mat readAssetImage(const AssetLocation& at)
{
	const std::vector<unsigned char> bytes = readAsset(at);
	cv::Mat img = bytes.empty() ? cv::Mat() : cv::imdecode(bytes, cv::IMREAD_COLOR);
	if (img.empty())
		throw InputError("'" + (at.archive.empty() ? at.member : at.archive + "/" + at.member) + "' is not a readable image");
	return img;
}

ExtractedAsset::ExtractedAsset(const AssetLocation& at)
{
	if (at.archive.empty())
	{
		m_path = at.member;
		return;
	}
	ZipHandle z = openArchive(at.archive);
	const fs::path member(at.member);
	const std::string folder = member.parent_path().generic_string() + "/";
	m_tempDir = makeTempDir();
	try
	{
		const zip_int64_t n = zip_get_num_entries(z.get(), 0);
		for (zip_int64_t i = 0; i < n; i++)
		{
			const std::string name = zip_get_name(z.get(), static_cast<zip_uint64_t>(i), 0);
			if (name.compare(0, folder.size(), folder) != 0 || name.back() == '/') continue;
			if (name.find("..") != std::string::npos) continue;  // never write outside the folder
			writeFile(m_tempDir / name, readMember(z.get(), at.archive, i));
		}
	}
	catch (...)
	{
		std::error_code ec;
		fs::remove_all(m_tempDir, ec);
		throw;
	}
	m_path = (m_tempDir / member).string();
}

ExtractedAsset::~ExtractedAsset()
{
	std::error_code ec;
	if (!m_tempDir.empty()) fs::remove_all(m_tempDir, ec);
}
}  // namespace vslam::world

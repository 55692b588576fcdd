#include <libvslam/core/InputError.h>
#include <libvslam/io/RawlogWriting.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>

namespace vslam
{
void writeActionFrameRawlog(const std::string& file, const std::vector<ActionFramePair>& steps)
{
	mrpt::io::CFileGZOutputStream out;
	if (!out.open(file)) throw InputError("cannot create rawlog '" + file + "'");
	auto arch = mrpt::serialization::archiveFrom(out);
	for (const auto& [action, sf] : steps) arch << *action << *sf;
}
std::string siblingFile(const std::string& rawlogFile, const std::string& suffix)
{
	std::filesystem::path p(rawlogFile);
	std::string name = p.filename().string();
	for (const char* ext : {".gz", ".rawlog"})
	{
		const std::string e(ext);
		if (name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0)
			name.resize(name.size() - e.size());
	}
	return (p.parent_path() / (name + suffix)).string();
}
}  // namespace vslam

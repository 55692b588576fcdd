#include <libvslam/core/ExceptionText.h>
#include <libvslam/core/InputError.h>
#include <libvslam/io/CCheckedGzInputStream.h>
#include <libvslam/io/COutputFile.h>
#include <libvslam/io/VSlamMapFile.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>

using namespace vslam;

bool vslam::isSerializedFile(const std::string& file)
{
	CCheckedGzInputStream in(file);
	const std::string head = in.peek(1);
	// A text map starts with a digit, a sign, a comment or a blank; an
	// MRPT object with 0x80 | its class name's length.
	return !head.empty() && (static_cast<unsigned char>(head[0]) & 0x80);
}

namespace
{
std::string readFailure(const std::exception& e, const CCheckedGzInputStream& stream)
{
	if (!stream.lastError().empty()) return stream.lastError();
	const std::string text = exceptionText(e);
	if (text.find("unknown serialization version") != std::string::npos)
		return "written by another vslam version (" + text + "; this vslam reads map format version 0)";
	if (text.find("not registered") != std::string::npos) return "not a vslam map (" + text + ")";
	return "truncated or corrupt (" + text + ")";
}
}  // namespace

CVSlamMap vslam::readVSlamMap(const std::string& file)
{
	const std::string name = "map file '" + file + "': ";
	CCheckedGzInputStream stream(file);
	mrpt::serialization::CSerializable::Ptr object;
	try
	{
		auto archive = mrpt::serialization::archiveFrom(stream);
		object = archive.ReadObject();
	}
	catch (const mrpt::serialization::CExceptionEOF&)
	{
		throw InputError(name + (stream.lastError().empty() ? "empty or truncated" : stream.lastError()));
	}
	catch (const std::exception& e)
	{
		throw InputError(name + readFailure(e, stream));
	}
	const auto map = std::dynamic_pointer_cast<CVSlamMap>(object);
	if (!map)
		throw InputError(name + "not a vslam map (it holds a " +
			(object ? object->GetRuntimeClass()->className : "null object") + ")");
	try
	{
		map->validate();
	}
	catch (const std::runtime_error& e)
	{
		throw InputError(name + e.what());
	}
	return std::move(*map);  // the object read is ours alone: no copy of its descriptors
}

void vslam::writeVSlamMap(const std::string& file, const CVSlamMap& map)
{
	mrpt::io::CMemoryStream buffer;
	auto archive = mrpt::serialization::archiveFrom(buffer);
	archive.WriteObject(&map);
	COutputFile out(file, COutputFile::Mode::Atomic);
	out.write(std::string(static_cast<const char*>(buffer.getRawBufferData()), buffer.getTotalBytesCount()));
	out.commit();
}

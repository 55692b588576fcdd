#include <libvslam/core/ActionOdometry.h>
#include <libvslam/core/ExceptionText.h>
#include <libvslam/core/InputError.h>
#include <libvslam/io/CCheckedGzInputStream.h>
#include <libvslam/io/CRawlogReader.h>
#include <mrpt/img/CImage.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <cmath>
#include <cstring>
#include <filesystem>

using namespace vslam;
using mrpt::serialization::CSerializable;

CRawlogReader::CRawlogReader(const std::string& fileName, std::optional<TIsolatedReadOptions> isolation)
	: m_fileName(fileName)
{
	m_stream = std::make_unique<CCheckedGzInputStream>(fileName);
	m_archive = mrpt::serialization::archiveUniquePtrFrom(*m_stream);
	mrpt::img::CImage::setImagesPathBase(imagesDirectory(fileName));
	if (isolation) m_unreadable = findUnreadableEntry(fileName, *isolation);
}

CRawlogReader::~CRawlogReader() = default;

double CRawlogReader::progress() const
{
	const uint64_t size = m_stream->getTotalBytesCount();
	return size == 0 ? 1.0 : std::min(1.0, double(m_stream->filePosition()) / double(size));
}

std::string CRawlogReader::imagesDirectory(const std::string& rawlogFile)
{
	const std::filesystem::path p(rawlogFile);
	std::string stem = p.filename().string();
	for (const char* ext : {".gz", ".rawlog"})
		if (stem.size() > std::strlen(ext) &&
			stem.compare(stem.size() - std::strlen(ext), std::string::npos, ext) == 0)
			stem.resize(stem.size() - std::strlen(ext));
	return (p.parent_path() / (stem + "_Images")).string();
}

void CRawlogReader::fail(size_t entry, const std::string& what) const
{
	throw InputError("rawlog '" + m_fileName + "', entry " + std::to_string(entry) + ": " + what);
}

CSerializable::Ptr CRawlogReader::readObject(size_t& entry)
{
	if (m_pending)
	{
		entry = m_pendingEntry;
		return std::move(m_pending);
	}
	if (m_eof) return nullptr;
	entry = m_objects;
	if (m_unreadable && m_unreadable->entry == entry) fail(entry, "corrupt data: " + m_unreadable->why);
	const uint64_t before = m_stream->getPosition();
	try
	{
		checkElementCount(entry);
		auto obj = m_archive->ReadObject();
		m_objects++;
		return obj;
	}
	catch (const mrpt::serialization::CExceptionEOF&)
	{
		// CArchive reports any failure inside an object header as EOF: it is
		// a clean end only if the stream is intact and nothing was consumed.
		if (!m_stream->lastError().empty()) fail(entry, m_stream->lastError());
		if (m_stream->getPosition() != before)
			fail(entry, "the file ends inside an object header (truncated)");
		m_eof = true;
		return nullptr;
	}
	catch (const InputError& e)
	{
		if (std::string(e.what()).rfind("rawlog '", 0) == 0) throw;  // names its entry already
		fail(entry, e.what());
	}
	catch (const std::exception& e)
	{
		// A short read of a cut file: the stream knows why.
		if (!m_stream->lastError().empty()) fail(entry, m_stream->lastError());
		const std::string text = exceptionText(e);
		if (text.find("not registered") != std::string::npos)
			fail(entry, text + " (a class this program does not know)");
		fail(entry, "cannot be read, the file is truncated or corrupt: " + text);
	}
}

void CRawlogReader::checkElementCount(size_t entry)
{
	// An MRPT object starts with 0x80 | name length, the class name and a
	// version byte; the containers then store their element count (uint32).
	const std::string head = m_stream->peek(1 + 127 + 1 + 4);
	if (head.empty() || !(static_cast<unsigned char>(head[0]) & 0x80)) return;
	const size_t nameLength = static_cast<unsigned char>(head[0]) & 0x7F;
	if (head.size() < 1 + nameLength + 1 + 4) return;  // MRPT reports the truncation
	const std::string name = head.substr(1, nameLength);
	if (name != "mrpt::obs::CSensoryFrame" && name != "mrpt::obs::CActionCollection") return;
	uint32_t count = 0;
	for (int i = 3; i >= 0; i--)  // little endian
		count = (count << 8) | static_cast<unsigned char>(head[1 + nameLength + 1 + i]);
	// Every element is a serialized object of at least 4 bytes (header,
	// name, version, end mark), and no real frame holds a million of them:
	// anything beyond is corrupt data, rejected before MRPT allocates it.
	constexpr uint32_t kMaxElements = 1'000'000;
	const uint64_t left = m_stream->remainingBytesBound();
	if (count > kMaxElements || uint64_t(count) * 4 > left)
		fail(entry, name + " claims " + std::to_string(count) + " elements (at most " +
			std::to_string(std::min<uint64_t>(kMaxElements, left / 4)) +
			" are possible here): the file is corrupt");
}

void CRawlogReader::checkOdometry(const mrpt::obs::CActionCollection& a, size_t entry) const
{
	const auto p = odometryIncrement(a);
	if (p && (!std::isfinite(p->x()) || !std::isfinite(p->y()) || !std::isfinite(p->phi())))
		fail(entry, "odometry increment is not finite (NaN or inf)");
	// No robot moves kilometres between two odometry readings: such a value
	// is corrupt data (and would overflow everything downstream).
	constexpr double kMaxIncrement = 1e4;  // m, rad
	if (p && (std::abs(p->x()) > kMaxIncrement || std::abs(p->y()) > kMaxIncrement || std::abs(p->phi()) > kMaxIncrement))
		fail(entry, "odometry increment (" + std::to_string(p->x()) + ", " + std::to_string(p->y()) + ", " +
			std::to_string(p->phi()) + ") is beyond any robot's motion between readings: corrupt data");
}

void CRawlogReader::scanObjects(const std::function<void(size_t entry)>& beforeEach)
{
	for (;;)
	{
		beforeEach(m_objects);
		size_t entry = 0;
		if (!readObject(entry)) return;
	}
}

bool CRawlogReader::next(RawlogStep& step)
{
	step = RawlogStep();
	for (;;)
	{
		size_t entry = 0;
		auto obj = readObject(entry);
		if (!obj) return false;
		step.entry = entry;

		if (auto acts = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(obj))
		{
			checkOdometry(*acts, entry);
			step.action = acts;
			size_t sfEntry = 0;
			auto next = readObject(sfEntry);
			if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(next))
				step.sf = sf;
			else
			{
				// An action without observations: keep what follows.
				m_pending = std::move(next);
				m_pendingEntry = sfEntry;
				step.sf = mrpt::obs::CSensoryFrame::Create();
			}
			if (auto mv = acts->getActionByClass<mrpt::obs::CActionRobotMovement2D>())
				step.timestamp = mv->timestamp;
			if (!step.sf->empty()) step.timestamp = (*step.sf->begin())->timestamp;
			m_format1Steps++;
			return true;
		}
		if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj))
		{
			step.sf = sf;
			if (!sf->empty()) step.timestamp = (*sf->begin())->timestamp;
			m_format1Steps++;
			return true;
		}
		if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obj))
		{
			const auto& p = odo->odometry;
			if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.phi()))
				fail(entry, "odometry reading is not finite (NaN or inf)");
			const mrpt::poses::CPose2D increment =
				m_lastOdometry ? p - *m_lastOdometry : mrpt::poses::CPose2D();
			m_lastOdometry = p;
			mrpt::obs::CActionRobotMovement2D mv;
			mv.computeFromOdometry(increment, mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
			mv.timestamp = odo->timestamp;
			step.action = mrpt::obs::CActionCollection::Create();
			step.action->insert(mv);
			step.sf = mrpt::obs::CSensoryFrame::Create();
			step.timestamp = odo->timestamp;
			m_format2Steps++;
			return true;
		}
		if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj))
		{
			// Group the observations taken at the same time (one image).
			step.sf = mrpt::obs::CSensoryFrame::Create();
			step.sf->insert(o);
			step.timestamp = o->timestamp;
			for (;;)
			{
				size_t e2 = 0;
				auto more = readObject(e2);
				auto o2 = std::dynamic_pointer_cast<mrpt::obs::CObservation>(more);
				if (o2 && !std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(o2) &&
					o2->timestamp == o->timestamp)
				{
					step.sf->insert(o2);
					continue;
				}
				m_pending = std::move(more);
				m_pendingEntry = e2;
				break;
			}
			m_format2Steps++;
			return true;
		}
		m_skipped++;  // some other serializable object: not for the filter
	}
}

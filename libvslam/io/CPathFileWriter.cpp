#include <libvslam/io/CPathFileWriter.h>
#include <libvslam/io/Trajectory.h>

using namespace vslam;

CPathFileWriter::CPathFileWriter(const std::string& file, Format format, const std::string& runId)
	: m_format(format), m_out(file, COutputFile::Mode::Streamed)
{
	if (format == Format::Tum)
	{
		m_out.print("# timestamp x y z qx qy qz qw\n");
		if (!runId.empty()) m_out.print("# vslam run %s\n", runId.c_str());
	}
	m_out.flush();
}

void CPathFileWriter::write(size_t step, double t, const se2::Pose& p)
{
	switch (m_format)
	{
		case Format::RbpfSlam:
			m_out.print("%u %f %f %f %f %f %f %f\n", static_cast<unsigned>(step), p.x, p.y, 0.0, p.phi, 0.0, 0.0, t);
			break;
		case Format::RbpfSlamOdometry:
			m_out.print("%i\t%f\t%f\t%f\t%f\t%f\t%f\n", static_cast<int>(step), p.x, p.y, 0.0, p.phi, 0.0, 0.0);
			break;
		case Format::Tum:
		{
			double q[4];
			yawToQuaternion(p.phi, q);
			m_out.print("%.6f %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n", t, p.x, p.y, 0.0, q[0], q[1], q[2], q[3]);
			break;
		}
	}
	m_out.flush();
}

void CPathFileWriter::writeUnknown(size_t step, double t)
{
	if (m_format == Format::Tum)
		m_out.print("# %.6f pose unknown\n", t);
	else
		m_out.print("%% %u %f pose unknown\n", static_cast<unsigned>(step), t);
	m_out.flush();
}

#include <libvslam/core/InputError.h>
#include <libvslam/eval/Trajectory.h>
#include <libvslam/io/CPathFileWriter.h>

using namespace vslam;

CPathFileWriter::CPathFileWriter(const std::string& file, Format format)
	: m_file(file), m_format(format)
{
	m_f = std::fopen(file.c_str(), "wt");
	if (!m_f) throw InputError("cannot create output file '" + file + "'");
	if (format == Format::Tum) std::fprintf(m_f, "# timestamp x y z qx qy qz qw\n");
	std::fflush(m_f);
}

CPathFileWriter::~CPathFileWriter()
{
	if (m_f) std::fclose(m_f);
}

void CPathFileWriter::write(size_t step, double t, const se2::Pose& p)
{
	switch (m_format)
	{
		case Format::RbpfSlam:
			std::fprintf(m_f, "%u %f %f %f %f %f %f %f\n", static_cast<unsigned>(step),
				p.x, p.y, 0.0, p.phi, 0.0, 0.0, t);
			break;
		case Format::RbpfSlamOdometry:
			std::fprintf(m_f, "%i\t%f\t%f\t%f\t%f\t%f\t%f\n", static_cast<int>(step), p.x,
				p.y, 0.0, p.phi, 0.0, 0.0);
			break;
		case Format::Tum:
		{
			double q[4];
			yawToQuaternion(p.phi, q);
			std::fprintf(m_f, "%.6f %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n", t, p.x, p.y,
				0.0, q[0], q[1], q[2], q[3]);
			break;
		}
	}
	if (std::fflush(m_f) != 0) throw InputError("cannot write to '" + m_file + "'");
}

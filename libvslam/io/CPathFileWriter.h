#pragma once
/** \file CPathFileWriter.h
 * Writes a trajectory row by row and flushes every row, so an interrupted
 * run leaves a valid file covering every step processed. Formats:
 *  - RbpfSlam: rbpf-slam's log_estimated_path.txt, no header,
 *    "%u %f %f %f %f %f %f %f" = step x y z yaw pitch roll timestamp;
 *  - RbpfSlamOdometry: rbpf-slam's log_odometry_path.txt rows,
 *    "%i\t%f\t%f\t%f\t%f\t%f\t%f" = step x y z yaw pitch roll;
 *  - Tum: "timestamp x y z qx qy qz qw" with a '#' header.
 */
#include <libvslam/models/SE2.h>

#include <cstdio>
#include <string>

namespace vslam
{
class CPathFileWriter
{
   public:
	enum class Format
	{
		RbpfSlam,
		RbpfSlamOdometry,
		Tum
	};

	/** Creates (truncates) the file; throws InputError on failure. */
	CPathFileWriter(const std::string& file, Format format);
	~CPathFileWriter();
	CPathFileWriter(const CPathFileWriter&) = delete;
	CPathFileWriter& operator=(const CPathFileWriter&) = delete;

	/** Appends one pose and flushes. t in UNIX seconds. */
	void write(size_t step, double t, const se2::Pose& pose);

   private:
	std::string m_file;
	Format m_format;
	FILE* m_f = nullptr;
};
}  // namespace vslam

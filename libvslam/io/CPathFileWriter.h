#pragma once
/** \file CPathFileWriter.h
 * Writes a trajectory row by row and flushes every row, so an interrupted
 * run leaves a valid file covering every step processed. Formats:
 *  - RbpfSlam: rbpf-slam's log_estimated_path.txt, no header,
 *    "%u %f %f %f %f %f %f %f" = step x y z yaw pitch roll timestamp;
 *  - RbpfSlamOdometry: rbpf-slam's log_odometry_path.txt rows,
 *    "%i\t%f\t%f\t%f\t%f\t%f\t%f" = step x y z yaw pitch roll;
 *  - Tum: "timestamp x y z qx qy qz qw" with a '#' header (and, if given,
 *    a second '#' line naming the run).
 * Every write is checked: a full disk is an OutputError naming the file.
 */
#include <libvslam/io/COutputFile.h>
#include <libvslam/models/SE2.h>

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

	/** Creates (truncates) the file; throws OutputError on failure. */
	CPathFileWriter(const std::string& file, Format format, const std::string& runId = "");
	/** Closes the file, checking that everything reached it. */
	void close() { m_out.commit(); }
	CPathFileWriter(const CPathFileWriter&) = delete;
	CPathFileWriter& operator=(const CPathFileWriter&) = delete;

	/** Appends one pose and flushes. t in UNIX seconds. */
	void write(size_t step, double t, const se2::Pose& pose);
	/** Marks a step whose pose is not known (global localization not yet
	 * done) with a comment row, which TUM tools and vslam-eval skip:
	 * "# t pose unknown" (TUM), "% step t pose unknown" (rbpf-slam). */
	void writeUnknown(size_t step, double t);

   private:
	Format m_format;
	COutputFile m_out;
};
}  // namespace vslam

#include <libvslam/config/StrictRead.h>
#include <libvslam/filter/CPreFilter.h>
#include <libvslam/obs/CObservationVisualLandmark.h>

#include <cmath>

using namespace vslam;
using namespace vslam::config;

void CPreFilter::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	max_ProjErrRMS =
		readDouble(c, s, "max_ProjErrRMS", max_ProjErrRMS, Range::nonNegative());
	min_NPoints = static_cast<uint32_t>(
		readInt(c, s, "min_NPoints", min_NPoints, Range::closed(0, 1e9)));
	max_Slope = readDouble(c, s, "max_Slope", max_Slope, Range::nonNegative());
}

void CPreFilter::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "max_ProjErrRMS", max_ProjErrRMS, 25, 12,
		"Reject if ProjErrRMS exceeds this [px] (paper: 3.0)");
	c.write(s, "min_NPoints", static_cast<int>(min_NPoints), 25, 12,
		"Reject if fewer matched features (paper: 10)");
	c.write(s, "max_Slope", max_Slope, 25, 12,
		"Reject if |Slope| exceeds this [rad] (paper: 0.1)");
}

CPreFilter::Verdict CPreFilter::check(double ProjErrRMS, uint32_t NPoints, double Slope) const
{
	// NaN statistics fail the comparisons below, so they are rejected.
	if (!(ProjErrRMS <= options.max_ProjErrRMS))
		return Verdict::RejectedProjErrRMS;
	if (NPoints < options.min_NPoints) return Verdict::RejectedNPoints;
	if (!(std::abs(Slope) <= options.max_Slope)) return Verdict::RejectedSlope;
	return Verdict::Accepted;
}

CPreFilter::Verdict CPreFilter::check(const CObservationVisualLandmark& o) const
{
	return check(o.ProjErrRMS, o.NPoints, o.Slope);
}

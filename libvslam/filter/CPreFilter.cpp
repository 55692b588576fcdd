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
	max_Height = readDouble(c, s, "max_Height", max_Height, Range::nonNegative());
	Slope_std_factor = readDouble(c, s, "Slope_std_factor", Slope_std_factor, Range::nonNegative());
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
	c.write(s, "max_Height", max_Height, 25, 12,
		"Reject if |Height| exceeds this [m]; 0: not checked (not in the paper)");
	c.write(s, "Slope_std_factor", Slope_std_factor, 25, 12,
		"Reject if |Slope| + this x SlopeStd exceeds max_Slope; 0: |Slope| alone (the paper)");
}

CPreFilter::Verdict CPreFilter::check(
	double ProjErrRMS, uint32_t NPoints, double Slope, double Height, double SlopeStd) const
{
	// NaN statistics fail the comparisons below, so they are rejected.
	if (!(ProjErrRMS <= options.max_ProjErrRMS))
		return Verdict::RejectedProjErrRMS;
	if (NPoints < options.min_NPoints) return Verdict::RejectedNPoints;
	const double slopeMargin = options.Slope_std_factor > 0 ? options.Slope_std_factor * SlopeStd : 0.0;
	if (!(std::abs(Slope) + slopeMargin <= options.max_Slope)) return Verdict::RejectedSlope;
	if (options.max_Height > 0 && !(std::abs(Height) <= options.max_Height)) return Verdict::RejectedHeight;
	return Verdict::Accepted;
}

CPreFilter::Verdict CPreFilter::check(const CObservationVisualLandmark& o) const
{
	return check(o.ProjErrRMS, o.NPoints, o.Slope, o.Height, o.SlopeStd);
}

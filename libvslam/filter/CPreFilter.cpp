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
	evidence_max_Slope = readDouble(c, s, "evidence_max_Slope", evidence_max_Slope, Range::nonNegative());
	above_evidence_noise_scale = readDouble(c, s, "above_evidence_noise_scale", above_evidence_noise_scale,
		Range::closed(1, 1000));
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
	c.write(s, "evidence_max_Slope", evidence_max_Slope, 25, 12,
		"Above this |Slope| [rad] an accepted measurement is no kidnap evidence; 0: all are");
	c.write(s, "above_evidence_noise_scale", above_evidence_noise_scale, 25, 12,
		"Std factor on the noise of measurements above evidence_max_Slope (>= 1)");
}

double CPreFilter::slopeUpperLimit(double Slope, double SlopeStd) const
{
	return std::abs(Slope) + (options.Slope_std_factor > 0 ? options.Slope_std_factor * SlopeStd : 0.0);
}

CPreFilter::Verdict CPreFilter::check(
	double ProjErrRMS, uint32_t NPoints, double Slope, double Height, double SlopeStd) const
{
	// NaN statistics fail the comparisons below, so they are rejected.
	if (!(ProjErrRMS <= options.max_ProjErrRMS))
		return Verdict::RejectedProjErrRMS;
	if (NPoints < options.min_NPoints) return Verdict::RejectedNPoints;
	if (!(slopeUpperLimit(Slope, SlopeStd) <= options.max_Slope)) return Verdict::RejectedSlope;
	if (options.max_Height > 0 && !(std::abs(Height) <= options.max_Height)) return Verdict::RejectedHeight;
	return Verdict::Accepted;
}

CPreFilter::Verdict CPreFilter::check(const CObservationVisualLandmark& o) const
{
	return check(o.ProjErrRMS, o.NPoints, o.Slope, o.Height, o.SlopeStd);
}

bool CPreFilter::isKidnapEvidence(double Slope, double SlopeStd) const
{
	return options.evidence_max_Slope <= 0 || slopeUpperLimit(Slope, SlopeStd) <= options.evidence_max_Slope;
}

bool CPreFilter::isKidnapEvidence(const CObservationVisualLandmark& o) const
{
	return isKidnapEvidence(o.Slope, o.SlopeStd);
}

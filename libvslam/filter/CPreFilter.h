#pragma once
/** \file CPreFilter.h
 * The paper's pre-filter: rejects unreliable visual measurements by an
 * acceptance region over their three statistics. Defaults are the paper's:
 * reject if ProjErrRMS > 3.0, or NPoints < 10, or |Slope| > 0.1; the first
 * violated rule (in that order) is reported. One rule beyond the paper, off
 * by default: |Height| > max_Height, the robot's height above the landmark
 * frame implied by the 6-DOF solution, which is 0 for a robot on a level
 * floor whatever the landmark's scale (Slope's twin for the translation).
 * And Slope's upper confidence bound: with Slope_std_factor k > 0, reject
 * if |Slope| + k SlopeStd > max_Slope, SlopeStd being the std of Slope the
 * pose solve predicts (0 where not known: then the paper's rule). A solve
 * that cannot tell the robot's tilt to within the bound is not trusted for
 * the pose either.
 * evidence_max_Slope (off by default) splits the region in two tiers: a
 * measurement accepted with |Slope| above it still weighs the particles
 * but is no evidence for the kidnap test (isKidnapEvidence), with its
 * noise std scaled by above_evidence_noise_scale.
 */
#include <mrpt/config/CLoadableOptions.h>

#include <cstdint>

namespace vslam
{
class CObservationVisualLandmark;

class CPreFilter
{
   public:
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		double max_ProjErrRMS = 3.0;  //!< pixels
		uint32_t min_NPoints = 10;
		double max_Slope = 0.1;  //!< on |Slope|, rad
		double max_Height = 0;  //!< on |Height|, m; 0: not checked
		/** k in |Slope| + k SlopeStd <= max_Slope; 0: the paper's |Slope|
		 * <= max_Slope. */
		double Slope_std_factor = 0;
		/** Kidnap evidence only up to this |Slope| (with Slope_std_factor,
		 * |Slope| + k SlopeStd), rad; 0: every accepted measurement. */
		double evidence_max_Slope = 0;
		/** Std factor on the noise of the measurements above
		 * evidence_max_Slope (>= 1; 1: the same noise as the others). */
		double above_evidence_noise_scale = 1;

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& cfg,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& cfg,
			const std::string& section) const override;
	};

	enum class Verdict : uint8_t
	{
		Accepted = 0,
		RejectedProjErrRMS,
		RejectedNPoints,
		RejectedSlope,
		RejectedHeight
	};

	CPreFilter() = default;
	explicit CPreFilter(const TOptions& o) : options(o) {}
	TOptions options;

	/** SlopeStd: Slope's predicted std, rad (0: not known). */
	Verdict check(double ProjErrRMS, uint32_t NPoints, double Slope, double Height, double SlopeStd = 0) const;
	Verdict check(const CObservationVisualLandmark& obs) const;
	/** For an accepted measurement: may the kidnap test count it? */
	bool isKidnapEvidence(double Slope, double SlopeStd = 0) const;
	bool isKidnapEvidence(const CObservationVisualLandmark& obs) const;

   private:
	/** |Slope|, plus Slope_std_factor x SlopeStd when that is set. */
	double slopeUpperLimit(double Slope, double SlopeStd) const;
};

}  // namespace vslam

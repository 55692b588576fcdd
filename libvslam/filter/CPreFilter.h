#pragma once
/** \file CPreFilter.h
 * The paper's pre-filter: rejects unreliable visual measurements by an
 * acceptance region over their three statistics. Defaults are the paper's:
 * reject if ProjErrRMS > 3.0, or NPoints < 10, or |Slope| > 0.1; the first
 * violated rule (in that order) is reported.
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
		/** On |Slope|, rad. The paper's 0.1 is for an unknown mount: on a level
		 * floor with the mount known, a tilt is the solve's error, and false
		 * recognitions show most of it. */
		double max_Slope = 0.02;

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
		RejectedSlope
	};

	CPreFilter() = default;
	explicit CPreFilter(const TOptions& o) : options(o) {}
	TOptions options;

	Verdict check(double ProjErrRMS, uint32_t NPoints, double Slope) const;
	Verdict check(const CObservationVisualLandmark& obs) const;
};

}  // namespace vslam

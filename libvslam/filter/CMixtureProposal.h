#pragma once
/** \file CMixtureProposal.h
 * The nominal/dual mixture of the paper (doc/mixture-proposal.md): each
 * particle's new pose is drawn from
 *
 *   q_i(s) = (1 - phi) p(s | s_i, u) + phi q_dual(s | z, l_i),
 *
 * and weighted by target / q_i (the deterministic-mixture weight), so
 * nominal and dual particles carry consistent importance factors by
 * construction. This class holds the options and the dynamic ratio rule.
 */
#include <mrpt/config/CLoadableOptions.h>

namespace vslam
{
class CMixtureProposal
{
   public:
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		/** Base share of dual particles (paper example: 20 of 200). */
		double dual_ratio = 0.1;
		/** Share of dual particles when no particle explains the
		 * measurements (the dynamic ratio rises towards it). */
		double dual_ratio_max = 0.5;
		/** Raise the ratio as the explained weight fraction falls. */
		bool dynamic_ratio = true;
		/** Draw duals only when they are sharper than the predicted cloud
		 * (det of position covariances); otherwise they waste particles. */
		bool dual_only_if_sharper = true;

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& cfg,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& cfg,
			const std::string& section) const override;
	};

	CMixtureProposal() = default;
	explicit CMixtureProposal(const TOptions& o) : options(o) {}
	TOptions options;

	/** The dual ratio phi for one frame in normal (non-kidnap) mode.
	 * \param explainedFraction weight fraction of particles explaining the
	 *        frame's best-explained measurement, in [0, 1]
	 * \param dualSharper whether the dual proposal is sharper than the
	 *        predicted particle cloud */
	double ratio(double explainedFraction, bool dualSharper) const;
};

}  // namespace vslam

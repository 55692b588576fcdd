#pragma once
/** \file CMixtureProposal.h
 * The nominal/dual mixture of the paper (doc/mixture-proposal.md): each
 * particle's new pose is drawn from
 *
 *   q_i(s) = (1 - phi) q_nominal(s | s_i, u, z) + phi q_dual(s | z, l_i),
 *
 * and weighted by target / q_i (the deterministic-mixture weight), so
 * nominal and dual particles carry consistent importance factors by
 * construction. The nominal component is the motion model (the paper) or,
 * by default, the motion model updated with the frame's measurements by an
 * EKF step (the "optimal" proposal of FastSLAM 2.0), which keeps the
 * weights even and the particle set diverse. This class holds the options
 * and the dynamic ratio rule.
 */
#include <mrpt/config/CLoadableOptions.h>

#include <cstdint>

namespace vslam
{
class CMixtureProposal
{
   public:
	enum class Nominal : uint8_t
	{
		Motion = 0,  //!< p(s | s_i, u): the paper's nominal particles
		Optimal = 1  //!< Gaussian approximation of p(s | s_i, u, z)
	};

	struct TOptions : public mrpt::config::CLoadableOptions
	{
		Nominal nominal_proposal = Nominal::Optimal;
		/** Base share of dual particles (paper example: 20 of 200). */
		double dual_ratio = 0.1;
		/** Share of dual particles when no particle explains the
		 * measurements: the ratio rises towards it as the explained weight
		 * fraction falls (equal to dual_ratio: a fixed share). */
		double dual_ratio_max = 0.5;
		/** Draw duals only where they can help: when they are sharper than
		 * the predicted cloud (det of position covariances) or the cloud
		 * misses the measurement; otherwise they waste particles. */
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
	 * \param dualUseful whether duals can help (see dual_only_if_sharper) */
	double ratio(double explainedFraction, bool dualUseful) const;
};

}  // namespace vslam

#pragma once
/** \file CRobustLikelihood.h
 * The measurement likelihood each particle is weighted with: a Gaussian
 * with a uniform outlier component (the paper notes the real errors are
 * heavier-tailed than Gaussian),
 *
 *   p(z | s, l) = (1 - eps) N(z; h(s, l), S) + eps / V,
 *
 * and the chi-square validation gate that decides whether a particle's
 * landmark filter takes the measurement. V is the volume of the
 * measurement space: (2 r)^2 2 pi for pose measurements, r 2 pi for
 * range-bearing, with r = outlier_max_range.
 */
#include <libvslam/models/LandmarkTypes.h>
#include <libvslam/models/MeasurementUpdate.h>
#include <mrpt/config/CLoadableOptions.h>

namespace vslam
{
class CRobustLikelihood
{
   public:
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		/** Probability that an accepted measurement is an outlier. */
		double outlier_probability = 0.05;
		/** Extent of the measurement space for the outlier density (m). */
		double outlier_max_range = 10.0;
		/** Probability mass inside the validation gate. */
		double gate_probability = 0.999;

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& cfg,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& cfg,
			const std::string& section) const override;
	};

	CRobustLikelihood() { setOptions(TOptions()); }
	explicit CRobustLikelihood(const TOptions& o) { setOptions(o); }

	void setOptions(const TOptions& o);
	const TOptions& options() const { return m_options; }

	/** log p(z | s, l) for an evaluated measurement. */
	double logLikelihood(
		const MeasurementEvaluation& e, LandmarkKind kind) const;
	/** True if the measurement lies inside the chi-square gate. */
	bool inGate(const MeasurementEvaluation& e) const;
	/** The gate threshold on the NIS for a measurement dimension (1..3). */
	double gate(int dim) const { return m_gate[dim]; }

   private:
	TOptions m_options;
	double m_logInlier = 0, m_logOutlierPose = 0, m_logOutlierPoint = 0;
	double m_gate[4] = {0, 0, 0, 0};
};

}  // namespace vslam

#include <libvslam/filter/CRelocalizationHypothesis.h>
#include <libvslam/models/CLandmarkModel.h>
#include <libvslam/models/Gaussian.h>
#include <libvslam/models/MeasurementUpdate.h>
#include <mrpt/bayes/CParticleFilterCapable.h>
#include <mrpt/random/RandomGenerators.h>

#include <cmath>
#include <limits>

using namespace vslam;

size_t vslam::mostInformativeMeasurement(const std::vector<KnownMeasurement>& ms)
{
	size_t best = 0;
	for (size_t k = 1; k < ms.size(); k++)
	{
		const auto& a = *ms[k].m;
		const auto& b = *ms[best].m;
		if (a.kind() != b.kind())
		{
			if (a.kind() == LandmarkKind::Pose) best = k;
		}
		else if (a.kind() == LandmarkKind::Point && a.z[0] < b.z[0])
			best = k;
	}
	return best;
}

void CRelocalizationHypothesis::clear()
{
	m_poses.clear();
	m_bank = LandmarkBank();
	m_support = 0;
	m_landmarks.clear();
}

double CRelocalizationHypothesis::logLikelihood(
	const se2::Pose& s, const std::vector<KnownMeasurement>& ms,
	const CRobustLikelihood& likelihood) const
{
	double sum = 0;
	for (const auto& k : ms)
	{
		if (k.slot >= m_bank.size()) continue;  // made after the hypothesis began: unknown to it
		const auto& model = landmarkModel(k.m->kind());
		sum += likelihood.logLikelihood(
			evaluateMeasurement(model, s, m_bank[k.slot], *k.m), k.m->kind());
	}
	return sum;
}

bool CRelocalizationHypothesis::start(
	const std::vector<KnownMeasurement>& ms, const LandmarkBank& bank, size_t n,
	const CRobustLikelihood& likelihood, mrpt::random::CRandomGenerator& rng)
{
	clear();
	if (ms.empty() || n == 0) return false;
	m_bank = bank;
	const KnownMeasurement& seed = ms[mostInformativeMeasurement(ms)];
	const CDualProposal dual =
		landmarkModel(seed.m->kind()).dualProposal(m_bank[seed.slot], *seed.m, HeadingPrior::Uniform());
	if (!dual.valid()) return false;
	std::vector<double> logW(n);
	m_poses.resize(n);
	for (size_t i = 0; i < n; i++)
	{
		m_poses[i] = dual.sample(rng);
		// Uniform prior: importance factor = likelihood / proposal density.
		logW[i] = logLikelihood(m_poses[i], ms, likelihood) - dual.logDensity(m_poses[i]);
	}
	resample(logW);
	m_support = 1;
	for (const auto& k : ms) m_landmarks.insert(k.m->key);
	return true;
}

void CRelocalizationHypothesis::startFrom(
	const std::vector<se2::Pose>& poses, const std::vector<double>& logW,
	const LandmarkBank& bank)
{
	clear();
	if (poses.empty()) return;
	m_bank = bank;
	m_poses = poses;
	resample(logW);
}

void CRelocalizationHypothesis::predict(
	const MotionPrior& motion, mrpt::random::CRandomGenerator& rng)
{
	if (!motion.moved()) return;
	for (auto& s : m_poses) s = motion.sample(rng, s);
}

double CRelocalizationHypothesis::explainedFraction(
	const std::vector<KnownMeasurement>& ms, const CRobustLikelihood& likelihood) const
{
	// Particles are equally weighted after every resampling.
	double best = 0;
	for (const auto& k : ms)
	{
		if (k.slot >= m_bank.size()) continue;  // made after the hypothesis began: unknown to it
		const auto& model = landmarkModel(k.m->kind());
		size_t inside = 0;
		for (const auto& s : m_poses)
			inside += likelihood.inGate(evaluateMeasurement(model, s, m_bank[k.slot], *k.m));
		best = std::max(best, double(inside) / double(m_poses.size()));
	}
	return best;
}

void CRelocalizationHypothesis::confirm(
	const std::vector<KnownMeasurement>& ms, const CRobustLikelihood& likelihood,
	mrpt::random::CRandomGenerator& rng)
{
	std::vector<double> logW(m_poses.size());
	for (size_t i = 0; i < m_poses.size(); i++)
		logW[i] = logLikelihood(m_poses[i], ms, likelihood);
	resample(logW);
	m_support++;
	for (const auto& k : ms) m_landmarks.insert(k.m->key);
}

void CRelocalizationHypothesis::resample(const std::vector<double>& logW)
{
	// MRPT's resampling draws from the global generator, as the filter's.
	std::vector<size_t> idx;
	mrpt::bayes::CParticleFilterCapable::computeResampling(
		mrpt::bayes::CParticleFilter::prSystematic, logW, idx);
	std::vector<se2::Pose> next(idx.size());
	for (size_t i = 0; i < idx.size(); i++) next[i] = m_poses[idx[i]];
	m_poses = std::move(next);
}

#pragma once
/** \file ScenarioRunner.h
 * Runs the filter over a simulated run through MRPT's
 * CParticleFilter::executeOn, as the app does, and reports position errors
 * against ground truth for the filter and for dead reckoning. */
#include <libvslam/filter/CVSlamParticleFilter.h>
#include <libvslam/sim/CMeasurementSimulator.h>
#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/random/RandomGenerators.h>

#include <algorithm>
#include <vector>

namespace vslam::testing
{
using PriorMap = std::vector<std::pair<LandmarkKey, LandmarkEstimate>>;

struct ScenarioResult
{
	std::vector<double> filterError, odometryError;  //!< per step, metres
	std::vector<se2::Pose> estimates;
	std::vector<size_t> kidnapIndices;  //!< indices (into the errors) of kidnaps
	/** Per step: the filter knew its pose, and had measured a mapped
	 * landmark while it did not (global localization). */
	std::vector<char> poseKnown, mappedLandmarkMeasured;
	TFilterStats stats;
	double rmse(const std::vector<double>& e, size_t from = 0) const
	{
		double s = 0;
		for (size_t i = from; i < e.size(); i++) s += e[i] * e[i];
		return std::sqrt(s / std::max<size_t>(1, e.size() - from));
	}
	double filterRmse() const { return rmse(filterError); }
	double odometryRmse() const { return rmse(odometryError); }
	static double median(std::vector<double> e)
	{
		std::nth_element(e.begin(), e.begin() + e.size() / 2, e.end());
		return e[e.size() / 2];
	}
};

/** The landmarks mapped before recording, as a map with the given error
 * (drawn from its own generator) and a matching covariance. */
inline PriorMap noisyPriorMap(
	const SimulatedRun& run, uint32_t seed, double stdXY, double stdPhi)
{
	mrpt::random::CRandomGenerator rng(seed);
	PriorMap map;
	for (const auto& L : run.landmarks)
	{
		if (!L.mappedBeforeRecording) continue;
		LandmarkEstimate l;
		l.kind = L.key.kind;
		l.mean << L.pose.x + stdXY * rng.drawGaussian1D_normalized(),
			L.pose.y + stdXY * rng.drawGaussian1D_normalized(),
			L.pose.phi + stdPhi * rng.drawGaussian1D_normalized();
		l.cov = Eigen::Vector3d(stdXY * stdXY, stdXY * stdXY, stdPhi * stdPhi).asDiagonal();
		map.push_back({L.key, l});
	}
	return map;
}

/** How a scenario starts: at the first true pose, or (global localization
 * in the prior map, which is then kept fixed) at an unknown one. */
enum class StartPose
{
	True,
	Unknown
};

inline ScenarioResult runScenario(
	const SimulatedRun& run, CVSlamParticleFilter::TOptions opts, uint32_t seed = 1,
	const PriorMap& priorMap = {}, StartPose start = StartPose::True)
{
	mrpt::random::getRandomGenerator().randomize(seed);
	// The first step's motion happened before truePose[0]: start at the
	// first true pose and skip step 0.
	opts.pf.initialPose = start == StartPose::True ? run.steps.front().truePose : se2::Pose{0, 0, 0};
	CVSlamParticleFilter filter(opts);
	if (!priorMap.empty()) filter.setPriorMap(priorMap, {}, start == StartPose::Unknown);
	if (start == StartPose::Unknown) filter.setPoseUnknown();
	mrpt::bayes::CParticleFilter pf;
	pf.m_options = opts.pf.toMrpt();
	ScenarioResult r;
	se2::Pose odo = run.steps.front().truePose;
	for (size_t i = 1; i < run.steps.size(); i++)
	{
		const auto& st = run.steps[i];
		pf.executeOn(filter, st.action.get(), st.sf.get());
		odo = se2::compose(odo, st.odometryIncrement);
		const se2::Pose est = filter.meanPose();
		r.estimates.push_back(est);
		r.filterError.push_back(std::hypot(est.x - st.truePose.x, est.y - st.truePose.y));
		r.odometryError.push_back(std::hypot(odo.x - st.truePose.x, odo.y - st.truePose.y));
		if (st.kidnappedHere) r.kidnapIndices.push_back(r.filterError.size() - 1);
		r.poseKnown.push_back(filter.poseKnown());
		r.mappedLandmarkMeasured.push_back(filter.stats().measurementsWhilePoseUnknown > 0);
	}
	r.stats = filter.stats();
	return r;
}
}  // namespace vslam::testing

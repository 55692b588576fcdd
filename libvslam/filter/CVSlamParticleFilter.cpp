#include <libvslam/core/ActionOdometry.h>
#include <libvslam/core/InputError.h>
#include <libvslam/filter/CVSlamParticleFilter.h>
#include <libvslam/filter/OptimalProposal.h>
#include <libvslam/models/CLandmarkModel.h>
#include <libvslam/models/ChiSquare.h>
#include <libvslam/models/MeasurementUpdate.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/random/RandomGenerators.h>

#include <Eigen/LU>
#include <algorithm>
#include <optional>
#include <cmath>
#include <numeric>

using namespace vslam;

CVSlamParticleFilter::CVSlamParticleFilter() : CVSlamParticleFilter(TOptions()) {}

CVSlamParticleFilter::CVSlamParticleFilter(const TOptions& o)
	: m_options(o),
	  m_motion(o.motion),
	  m_likelihood(o.likelihood),
	  m_mixture(o.mixture),
	  m_kidnap(o.kidnap),
	  m_rng(mrpt::random::getRandomGenerator())
{
	m_extractor.visual = o.visual;
	m_extractor.rangeBearing = o.rangeBearing;
	m_extractor.headingChange = o.headingChange;
	m_extractor.preFilter.options = o.prefilter;
	reset();
}

void CVSlamParticleFilter::reset()
{
	const auto& pf = m_options.pf;
	m_particles.clear();
	m_particles.resize(pf.sampleSize);
	for (auto& p : m_particles)
	{
		p.log_w = 0;
		p.d = CVSlamParticle();
		p.d.pose = pf.initialPose;
		if (pf.initial_std_xy > 0 || pf.initial_std_phi > 0)
			p.d.pose = se2::compose(
				pf.initialPose,
				{pf.initial_std_xy * m_rng.drawGaussian1D_normalized(),
				 pf.initial_std_xy * m_rng.drawGaussian1D_normalized(),
				 pf.initial_std_phi * m_rng.drawGaussian1D_normalized()});
	}
	m_index = CLandmarkIndex();
	m_odometry = COdometryAccumulator();
	m_lastKidnap.reset();
	m_kidnap = CKidnapDetector(m_options.kidnap);
	m_stats = TFilterStats();
	m_lastFrame = TFrameReport();
	m_graph.reset();
	if (m_options.loopClosure.enabled) m_graph.emplace(m_options.loopClosure, pf.initialPose);
}

void CVSlamParticleFilter::setPriorMap(
	const std::vector<std::pair<LandmarkKey, LandmarkEstimate>>& map,
	mrpt::Clock::time_point t, bool fixed)
{
	m_mapFixed = fixed;
	LandmarkBank bank = m_particles.empty() ? LandmarkBank() : m_particles[0].d.bank;
	for (const auto& [key, estimate] : map)
	{
		if (m_index.find(key)) throw std::invalid_argument("duplicate landmark in prior map");
		m_index.add(key, t);
		bank.push_back(estimate);
	}
	for (auto& p : m_particles) p.d.bank = bank;
	// The prior map is the frame; the pose graph would let it move.
	m_graph.reset();
}

void CVSlamParticleFilter::setPoseUnknown()
{
	if (m_index.size() == 0) throw std::logic_error("an unknown start pose needs a prior map to find it in");
	if (!m_options.kidnap.enabled) throw std::logic_error("an unknown start pose needs the kidnap test ([vslam_kidnap] enabled)");
	m_poseUnknown = true;
}

// --------------------------------------------------------------------------
// Inputs
// --------------------------------------------------------------------------
void CVSlamParticleFilter::addOdometryIncrement(
	const se2::Pose& u, std::optional<mrpt::Clock::time_point> end)
{
	if (!std::isfinite(u.x) || !std::isfinite(u.y) || !std::isfinite(u.phi))
		throw InputError("odometry increment is not finite (NaN or inf)");
	m_odometry.add(u, m_motion.incrementCovariance(u));
	// References serve only heading changes; without them they are work on every reading.
	if (end && m_options.headingChange.enabled) m_odometry.setHeadingReference(*end);
}

void CVSlamParticleFilter::prediction_and_update_pfStandardProposal(
	const mrpt::obs::CActionCollection* action,
	const mrpt::obs::CSensoryFrame* sf,
	const mrpt::bayes::CParticleFilter::TParticleFilterOptions& /*o*/)
{
	// MRPT's executeOn() rethrows everything wrapped in its own exception
	// type, so the message of bad input is kept for takeInputError().
	try
	{
		if (action)
			if (const auto u = odometryIncrement(*action))
				addOdometryIncrement(u->asTPose(), odometryTime(*action));
		if (sf) processFrame(m_extractor.extract(*sf));
	}
	catch (const InputError& e)
	{
		m_inputError = e.what();
		throw;
	}
}

std::string CVSlamParticleFilter::takeInputError()
{
	std::string e;
	e.swap(m_inputError);
	return e;
}

void CVSlamParticleFilter::processFrame(const FrameMeasurements& frame)
{
	// A heading change corrects the odometry the particles are drawn from
	// next, at this frame or a later one.
	if (frame.headingChange && m_options.headingChange.enabled) fuseHeadingChange(*frame.headingChange);
	// One importance weight for all the frame's measurements: an image's
	// measurements are not independent draws in time.
	if (!frame.empty()) updateWithFrame(frame);
}

void CVSlamParticleFilter::fuseHeadingChange(const HeadingChangeMeasurement& h)
{
	const double gate = chiSquareQuantile(m_options.headingChange.gate_probability, 1);
	switch (m_odometry.fuseHeadingChange(h.from, h.to, h.dphi, h.variance, gate))
	{
		case COdometryAccumulator::HeadingFusion::Fused:
			m_stats.headingChangesFused++;
			break;
		case COdometryAccumulator::HeadingFusion::Gated:
			m_stats.headingChangesGated++;
			break;
		case COdometryAccumulator::HeadingFusion::NoReference:
			m_stats.headingChangesWithoutReference++;
			break;
	}
}

// --------------------------------------------------------------------------
// One update
// --------------------------------------------------------------------------
void CVSlamParticleFilter::updateWithFrame(const FrameMeasurements& frame)
{
	m_stats.frames++;
	m_lastFrame = TFrameReport();
	m_lastFrame.timestamp = frame.timestamp;
	std::vector<KnownMeasurement> known;
	std::vector<const LandmarkMeasurement*> firstSightings;
	splitByLandmark(frame, known, firstSightings);
	m_lastFrame.measurements = known.size();

	// Which measurements the predicted particle cloud explains, and what the
	// kidnap test makes of it.
	const MotionPrior mp(m_odometry, m_motion);
	Eigen::Matrix2d spreadXY = Eigen::Matrix2d::Zero();
	const bool optimal = m_options.mixture.nominal_proposal == CMixtureProposal::Nominal::Optimal;
	std::vector<PoseGaussianProposal>& proposals = m_proposalBuffer;
	if (!known.empty()) explainedFractions(known, mp, spreadXY, optimal ? &proposals : nullptr);
	double bestFraction = 0;
	const auto verdict = kidnapVerdict(frame.timestamp, known, mp, bestFraction);

	// A kidnap declared or reverted moves the whole cloud: the odometry
	// since the last frame no longer links the poses.
	const bool cloudMoved = verdict == CKidnapDetector::Verdict::Kidnapped ||
		verdict == CKidnapDetector::Verdict::Reverted;
	LandmarksToPlace toReinitialize;  // stays empty with a fixed map: no landmark is suspect
	std::vector<KnownMeasurement> used;
	if (cloudMoved)
	{
		// The hypothesis already holds this frame's evidence and motion.
		if (verdict == CKidnapDetector::Verdict::Kidnapped)
			switchToRelocalizationHypothesis(frame.timestamp);
		else
			revertLastKidnap();
		for (const auto& k : known)
			if (m_index.entry(k.slot).suspect) toReinitialize.emplace_back(k.slot, k.m);
	}
	else
	{
		// Measurements no particle could explain, even allowing an odometry
		// slip, are outliers: not used. Landmarks placed while the robot was
		// lost are re-initialized. (A landmark that stays unexplained while
		// the robot is localized is not moved: a consistent false
		// recognition would move a correct landmark.)
		for (const auto& k : known)
		{
			if (m_poseUnknown)
				m_stats.measurementsWhilePoseUnknown++;
			else if (m_index.entry(k.slot).suspect)
				toReinitialize.emplace_back(k.slot, k.m);
			else if (k.plausibleFraction >= m_options.kidnap.explained_min_fraction)
				used.push_back(k);
			else
				m_stats.rejectedUnexplained++;
		}
		if (used.empty())
			sampleMotionOnly(mp);
		else
			normalUpdate(used, mp, spreadXY, bestFraction, optimal ? &proposals : nullptr);
	}
	if (m_graph)
	{
		m_graph->addOdometry(m_odometry.mean(), m_odometry.cov());
		if (cloudMoved) m_graph->loseOdometry();
	}
	m_odometry.reset();
	PlacedLandmarks placed;
	if (m_mapFixed || m_poseUnknown)
		m_stats.landmarksNotPlaced += firstSightings.size() + frame.creations.size();
	else
		placed = placeLandmarks(frame, firstSightings, toReinitialize);
	if (m_graph) updateLoopClosureGraph(frame.timestamp, used, placed);
	for (auto& p : m_particles) p.d.path.push(frame.timestamp, p.d.pose);
	m_lastFrame.essAfterUpdate = ESS();
}

void CVSlamParticleFilter::splitByLandmark(const FrameMeasurements& frame, std::vector<KnownMeasurement>& known,
	std::vector<const LandmarkMeasurement*>& firstSightings) const
{
	for (const auto& m : frame.measurements)
	{
		if (const auto slot = m_index.find(m.key))
			known.push_back({&m, *slot});
		else if (std::none_of(
					 firstSightings.begin(), firstSightings.end(), [&](const auto* f) { return f->key == m.key; }))
			firstSightings.push_back(&m);
	}
}

CKidnapDetector::Verdict CVSlamParticleFilter::kidnapVerdict(mrpt::Clock::time_point t,
	const std::vector<KnownMeasurement>& known, const MotionPrior& mp, double& bestFraction)
{
	const double minFraction = m_options.kidnap.explained_min_fraction;
	std::vector<CKidnapDetector::Evidence> evidence;
	bestFraction = 0;
	for (const auto& k : known)
	{
		// A landmark placed while the robot was lost is placed again from this
		// measurement, not weighed against the belief it contradicts.
		const auto& entry = m_index.entry(k.slot);
		if (entry.suspect) continue;
		// An unknown pose explains nothing: every mapped landmark is evidence for the hypothesis.
		evidence.push_back({k, entry.created, !m_poseUnknown && k.plausibleFraction >= minFraction});
		bestFraction = std::max(bestFraction, k.explainedFraction);
	}
	m_lastFrame.explainedFraction = bestFraction;
	const auto verdict = m_kidnap.update(
		t, evidence, {mp, m_particles[bestParticleIndex()].d.bank, m_particles.size(), m_likelihood, m_rng});
	m_stats.unexplainedFrames +=
		verdict == CKidnapDetector::Verdict::Unexplained || verdict == CKidnapDetector::Verdict::Kidnapped;
	m_lastFrame.hypothesisSupport = m_kidnap.hypothesis().support();
	return verdict;
}

CVSlamParticleFilter::PlacedLandmarks CVSlamParticleFilter::placeLandmarks(const FrameMeasurements& frame,
	const std::vector<const LandmarkMeasurement*>& firstSightings, const LandmarksToPlace& toReinitialize)
{
	// The first landmark fixes the map's frame: see anchorMapFrame().
	const bool createsFirstLandmark = m_index.size() == 0 && (!firstSightings.empty() || !frame.creations.empty());
	if (createsFirstLandmark && m_options.landmarks.anchor_first_landmark) anchorMapFrame();
	// New landmarks start from each particle's own (new) pose.
	PlacedLandmarks placed;
	for (const auto* m : firstSightings)
	{
		createLandmark(m->key, *m, frame.timestamp);
		placed.emplace_back(m_index.size() - 1, *m);
		m_stats.landmarksCreatedFromMeasurement++;
	}
	for (const auto& [slot, m] : toReinitialize)
	{
		reinitializeLandmark(slot, *m, frame.timestamp);
		placed.emplace_back(slot, *m);
	}
	const double xy = m_options.landmarks.init_std_xy, phi = m_options.landmarks.init_std_phi;
	const Eigen::Matrix3d initCov = Eigen::Vector3d(xy * xy, xy * xy, phi * phi).asDiagonal();
	for (const auto& c : frame.creations)
	{
		LandmarkMeasurement rel = c.relative;
		rel.R = MatN(Eigen::Matrix3d(rel.R) + initCov);
		if (const auto slot = m_index.find(c.key))
		{
			m_stats.duplicateCreations++;
			reinitializeLandmark(*slot, rel, frame.timestamp);
			placed.emplace_back(*slot, rel);
		}
		else
		{
			createLandmark(c.key, rel, frame.timestamp);
			placed.emplace_back(m_index.size() - 1, rel);
			m_stats.landmarksCreated++;
		}
	}
	return placed;
}

void CVSlamParticleFilter::moveParticlesTo(const std::vector<se2::Pose>& poses)
{
	// They carry the current map of the best particle (which also holds
	// the landmarks created since the hypothesis started).
	const LandmarkBank bank = m_particles[bestParticleIndex()].d.bank;
	for (size_t i = 0; i < m_particles.size(); i++)
	{
		m_particles[i].d.pose = poses[i % poses.size()];
		m_particles[i].d.bank = bank;
		m_particles[i].log_w = 0;
	}
}

void CVSlamParticleFilter::switchToRelocalizationHypothesis(mrpt::Clock::time_point t)
{
	// The paper's kidnap mode: only dual particles, importance factors from
	// a uniform prior. They were drawn and tested by the detector. The
	// cloud left behind stays with the detector, in case of a return.
	std::vector<se2::Pose> left(m_particles.size());
	std::vector<double> leftLogW(m_particles.size());
	for (size_t i = 0; i < m_particles.size(); i++)
	{
		left[i] = m_particles[i].d.pose;
		leftLogW[i] = m_particles[i].log_w;
	}
	const LandmarkBank leftBank = m_particles[bestParticleIndex()].d.bank;
	moveParticlesTo(m_kidnap.hypothesis().poses());
	if (m_poseUnknown)
	{
		// Found, not kidnapped: the cloud left was never a belief to return to.
		m_kidnap.acceptHypothesis({}, {}, leftBank);
		m_poseUnknown = false;
		m_lastFrame.poseFound = true;
		m_stats.dualParticlesDrawn += m_particles.size();
		return;
	}
	m_kidnap.acceptHypothesis(left, leftLogW, leftBank);
	m_stats.kidnapsDetected++;
	m_stats.dualParticlesDrawn += m_particles.size();
	m_lastFrame.kidnapDeclared = true;
	m_lastFrame.dualRatio = 1;
	m_lastFrame.dualParticles = m_particles.size();
	// Landmarks created since the last verified frame were placed from a
	// pose the robot did not have; streaks so far were the kidnap's doing.
	m_lastKidnap = LastKidnap{t, {}};
	m_index.forEachEntry([&](CLandmarkIndex::Entry& e) {
		if (!m_mapFixed && !m_kidnap.anchored(e.created) && !e.suspect)
		{
			e.suspect = true;
			m_lastKidnap->markedSuspect.push_back(e.key);
		}
	});
}

void CVSlamParticleFilter::revertLastKidnap()
{
	moveParticlesTo(m_kidnap.returnHypothesis().poses());
	m_kidnap.clearReturnHypothesis();
	m_stats.kidnapsReverted++;
	m_lastFrame.kidnapReverted = true;
	// Back to the belief the kidnap interrupted: what the kidnap made
	// suspect is sound again, and what was placed since is suspect.
	if (!m_lastKidnap) return;
	for (const auto& key : m_lastKidnap->markedSuspect)
		if (const auto slot = m_index.find(key)) m_index.entry(*slot).suspect = false;
	m_index.forEachEntry([&](CLandmarkIndex::Entry& e) {
		if (!m_mapFixed && e.created >= m_lastKidnap->time) e.suspect = true;
	});
	m_lastKidnap.reset();
}

void CVSlamParticleFilter::sampleMotionOnly(const MotionPrior& mp)
{
	if (!mp.moved()) return;
	for (auto& p : m_particles) p.d.pose = mp.sample(m_rng, p.d.pose);
}

void CVSlamParticleFilter::explainedFractions(
	std::vector<KnownMeasurement>& known, const MotionPrior& mp, Eigen::Matrix2d& spreadXY,
	std::vector<PoseGaussianProposal>* proposals) const
{
	const std::vector<double> w = normalizedLinearWeights();
	Eigen::Vector2d mean = Eigen::Vector2d::Zero();
	Eigen::Matrix2d second = Eigen::Matrix2d::Zero(), motionXY = Eigen::Matrix2d::Zero();
	if (proposals) proposals->resize(m_particles.size());
	std::vector<char> inGate(known.size());
	size_t i = 0;
	for (auto it = m_particles.begin(); it != m_particles.end(); ++it, ++i)
	{
		const CVSlamParticle& p = it->d;
		const se2::Pose predicted = se2::compose(p.pose, mp.increment());
		const Eigen::Matrix3d C = mp.globalCov(p.pose);
		const Eigen::Vector2d xy(predicted.x, predicted.y);
		mean += w[i] * xy;
		second += w[i] * xy * xy.transpose();
		motionXY += w[i] * C.topLeftCorner<2, 2>();
		if (proposals)
			(*proposals)[i] = optimalProposal(predicted, C, p.bank, known, m_likelihood, &inGate);
		std::optional<Eigen::Matrix3d> slip;
		for (size_t k = 0; k < known.size(); k++)
		{
			auto& km = known[k];
			const auto& model = landmarkModel(km.m->kind());
			const auto& l = p.bank[km.slot];
			const bool explained = proposals
				? inGate[k] != 0
				: m_likelihood.inGate(evaluateMeasurement(model, predicted, l, *km.m, &C));
			if (explained)
			{
				km.explainedFraction += w[i];
				km.plausibleFraction += w[i];
				continue;
			}
			if (!slip) slip = mp.globalSlipCov(p.pose);
			if (m_likelihood.inGate(evaluateMeasurement(model, predicted, l, *km.m, &*slip)))
				km.plausibleFraction += w[i];
		}
	}
	spreadXY = second - mean * mean.transpose() + motionXY;
}

double CVSlamParticleFilter::weighAndUpdateLandmarks(
	CVSlamParticle& p, const se2::Pose& s, const std::vector<KnownMeasurement>& used)
{
	double logLik = 0;
	for (const auto& k : used)
	{
		const auto& model = landmarkModel(k.m->kind());
		const auto e = evaluateMeasurement(model, s, p.bank[k.slot], *k.m);
		logLik += m_likelihood.logLikelihood(e, k.m->kind());
		// Only the observed landmark's filter is updated, and only if the
		// measurement passes this particle's validation gate.
		if (!m_mapFixed && m_likelihood.inGate(e)) kalmanUpdate(p.bank.mutate(k.slot), e);
	}
	return logLik;
}

void CVSlamParticleFilter::normalUpdate(
	const std::vector<KnownMeasurement>& used, const MotionPrior& mp,
	const Eigen::Matrix2d& spreadXY, double explainedFraction,
	const std::vector<PoseGaussianProposal>* proposals)
{
	const size_t N = m_particles.size();
	const size_t kStar = mostInformativeMeasurement(used);
	const LandmarkMeasurement& mStar = *used[kStar].m;
	const auto& modelStar = landmarkModel(mStar.kind());
	const double headingStd = std::sqrt(mp.cov()(2, 2));
	const auto dualFor = [&](const CVSlamParticle& p) {
		return modelStar.dualProposal(
			p.bank[used[kStar].slot], mStar,
			HeadingPrior::Gaussian(se2::compose(p.pose, mp.increment()).phi, headingStd));
	};

	// The dual ratio for this frame (zero when duals cannot help).
	double phi = 0;
	const auto& mo = m_options.mixture;
	if (mo.dual_ratio > 0 || mo.dual_ratio_max > 0)
	{
		// Duals help where the measurement is sharper than the predicted
		// cloud, or where the cloud misses it (odometry slipped).
		const CDualProposal q = dualFor(m_particles[bestParticleIndex()].d);
		const bool useful = q.valid() &&
			(q.positionSpread().determinant() < spreadXY.determinant() ||
			 explainedFraction < 0.5);
		phi = m_mixture.ratio(explainedFraction, useful);
	}
	const size_t nDual = std::min(N, static_cast<size_t>(std::lround(phi * N)));
	// With exactly nDual duals in a uniformly random subset, each particle
	// is dual with probability nDual / N: that is its mixture weight.
	phi = static_cast<double>(nDual) / static_cast<double>(N);
	std::vector<char> isDual(N, 0);
	if (nDual > 0)
	{
		std::vector<size_t> order(N);
		std::iota(order.begin(), order.end(), size_t(0));
		for (size_t i = 0; i < nDual; i++)  // partial Fisher-Yates
		{
			const size_t j = i + m_rng.drawUniform32bit() % (N - i);
			std::swap(order[i], order[j]);
			isDual[order[i]] = 1;
		}
	}
	const double logPhi = std::log(phi), log1mPhi = std::log1p(-phi);

	size_t i = 0;
	for (auto it = m_particles.begin(); it != m_particles.end(); ++it, ++i)
	{
		CVSlamParticle& p = it->d;
		const se2::Pose prev = p.pose;
		// The particle's proposal: a nominal component (motion model, or
		// motion updated with the measurements, computed by
		// explainedFractions()) and a dual one.
		std::optional<CDualProposal> nominal, dual;
		if (proposals && (*proposals)[i].valid) nominal = CDualProposal((*proposals)[i]);
		if (nDual > 0)
			if (auto q = dualFor(p); q.valid()) dual = q;
		se2::Pose s;
		if (dual && isDual[i])
		{
			s = dual->sample(m_rng);
			m_stats.dualParticlesDrawn++;
		}
		else
			s = nominal ? nominal->sample(m_rng) : mp.sample(m_rng, prev);
		// log p_motion(s) - log q_i(s): zero when sampling the motion model.
		double logCorrection = 0;
		if (nominal || dual)
		{
			const double lm = mp.logDensity(prev, s);
			const double ln = nominal ? nominal->logDensity(s) : lm;
			const double lq =
				dual ? logSumExp(log1mPhi + ln, logPhi + dual->logDensity(s)) : ln;
			logCorrection = lm - lq;
		}
		it->log_w += weighAndUpdateLandmarks(p, s, used) + logCorrection;
		p.pose = s;
	}
	for (const auto& k : used) m_index.entry(k.slot).measurements++;
	m_stats.measurementsUsed += used.size();
	m_lastFrame.used = used.size();
	m_lastFrame.dualRatio = phi;
	m_lastFrame.dualParticles = nDual;
}

void CVSlamParticleFilter::createLandmark(
	const LandmarkKey& key, const LandmarkMeasurement& rel, mrpt::Clock::time_point t)
{
	m_index.add(key, t);
	const auto& model = landmarkModel(key.kind);
	// FastSLAM proper: each particle's own pose carries where the robot was;
	// widening every landmark by the whole cloud's spread would let loop
	// closures move landmarks instead of weighing particles.
	for (auto& p : m_particles) p.d.bank.push_back(model.initialize(p.d.pose, rel));
}

void CVSlamParticleFilter::anchorMapFrame()
{
	// With no landmark yet, no measurement has weighed the particles: their
	// spread is the odometry's alone, and it is the spread of the frame the
	// map is about to be built in. Nothing seen later can tell those frames
	// apart (each particle's map is consistent with its own), so resampling
	// would keep one at random and the whole map would take its error. The
	// cloud's mean is the best estimate of that frame: every particle takes
	// it, and the first landmark is placed from there.
	const se2::Pose mean = cloudMean(normalizedLinearWeights());
	for (auto& p : m_particles)
	{
		p.d.pose = mean;
		p.log_w = 0;
	}
}

void CVSlamParticleFilter::updateLoopClosureGraph(
	mrpt::Clock::time_point t, const std::vector<KnownMeasurement>& used,
	const std::vector<std::pair<size_t, LandmarkMeasurement>>& placed)
{
	if (used.empty() && placed.empty()) return;
	m_graph->addKeyframe(t, m_particles[bestParticleIndex()].d.pose);
	bool closesLoop = false;
	for (const auto& k : used)
		if (m_graph->hasLandmark(k.slot)) closesLoop |= m_graph->addMeasurement(k.slot, *k.m);
	for (const auto& [slot, m] : placed) m_graph->placeLandmark(slot, m);
	if (closesLoop) applyLoopClosure(m_graph->optimize());
}

void CVSlamParticleFilter::applyLoopClosure(const CLandmarkPoseGraph::Correction& c)
{
	// Every particle takes the solution's map (with the best particle's
	// landmark covariances), and the cloud moves rigidly so that its
	// weighted mean (the online estimate) sits on the solution's current
	// pose: the spread and the weights stay as they are. (Moving the best
	// particle there instead carries the mean past the solution by the best
	// particle's offset from it.)
	m_stats.loopClosures++;
	m_stats.loopClosureEdgesLeftOut = c.leftOutEdges;
	const CVSlamParticle& best = m_particles[bestParticleIndex()].d;
	LandmarkBank bank = best.bank;
	for (const auto& l : c.landmarks)
	{
		LandmarkEstimate e = bank[l.slot];
		if (l.kind == LandmarkKind::Point)
			e.mean.head<2>() = Eigen::Vector2d(l.pose.x, l.pose.y);
		else
			e.mean = se2::toVector(l.pose);
		bank.set(l.slot, e);
	}
	const se2::Pose anchor = cloudMean(normalizedLinearWeights());
	const se2::Pose shift = se2::compose(c.keyframe, se2::inverse(anchor));
	for (auto& p : m_particles)
	{
		p.d.pose = se2::compose(shift, p.d.pose);
		p.d.bank = bank;
	}
}

void CVSlamParticleFilter::reinitializeLandmark(
	size_t slot, const LandmarkMeasurement& m, mrpt::Clock::time_point t)
{
	auto& entry = m_index.entry(slot);
	// Re-placed from the current belief: young again for kidnap evidence.
	entry.created = t;
	entry.suspect = false;
	entry.reinitializations++;
	m_stats.landmarksReinitialized++;
	const auto& model = landmarkModel(entry.key.kind);
	for (auto& p : m_particles) p.d.bank.set(slot, model.initialize(p.d.pose, m));
}

// --------------------------------------------------------------------------
// Outputs and CParticleFilterCapable
// --------------------------------------------------------------------------
std::vector<double> CVSlamParticleFilter::normalizedLinearWeights() const
{
	std::vector<double> w(m_particles.size());
	double maxW = -std::numeric_limits<double>::infinity();
	for (const auto& p : m_particles) maxW = std::max(maxW, p.log_w);
	double sum = 0;
	for (size_t i = 0; i < w.size(); i++)
		sum += (w[i] = std::exp(m_particles[i].log_w - maxW));
	for (auto& x : w) x /= sum;
	return w;
}

namespace
{
/** Weighted mean of poseOf(0 .. w.size()-1), circular in phi. */
template <typename PoseOf>
se2::Pose weightedMean(const std::vector<double>& w, PoseOf poseOf)
{
	double x = 0, y = 0, c = 0, s = 0;
	for (size_t i = 0; i < w.size(); i++)
	{
		const se2::Pose q = poseOf(i);
		x += w[i] * q.x;
		y += w[i] * q.y;
		c += w[i] * std::cos(q.phi);
		s += w[i] * std::sin(q.phi);
	}
	return {x, y, std::atan2(s, c)};
}
}  // namespace

se2::Pose CVSlamParticleFilter::meanPose() const
{
	return weightedMean(normalizedLinearWeights(), [&](size_t i) {
		return se2::compose(m_particles[i].d.pose, m_odometry.mean());
	});
}

se2::Pose CVSlamParticleFilter::cloudMean(const std::vector<double>& w) const
{
	return weightedMean(w, [&](size_t i) { return m_particles[i].d.pose; });
}

Eigen::Matrix3d CVSlamParticleFilter::poseCovariance() const
{
	const std::vector<double> w = normalizedLinearWeights();
	const se2::Pose mean = cloudMean(w);
	Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
	for (size_t i = 0; i < w.size(); i++)
	{
		const Eigen::Vector3d d = se2::difference(m_particles[i].d.pose, mean);
		C += w[i] * d * d.transpose();
	}
	return C;
}

size_t CVSlamParticleFilter::bestParticleIndex() const
{
	size_t best = 0;
	for (size_t i = 1; i < m_particles.size(); i++)
		if (m_particles[i].log_w > m_particles[best].log_w) best = i;
	return best;
}

double CVSlamParticleFilter::normalizeWeights(double* out_max_log_w)
{
	if (m_particles.empty()) return 0;
	double maxW = -std::numeric_limits<double>::infinity();
	double minW = std::numeric_limits<double>::infinity();
	for (const auto& p : m_particles)
	{
		maxW = std::max(maxW, p.log_w);
		minW = std::min(minW, p.log_w);
	}
	for (auto& p : m_particles) p.log_w -= maxW;
	if (out_max_log_w) *out_max_log_w = maxW;
	return std::exp(maxW - minW);
}

double CVSlamParticleFilter::ESS() const
{
	if (m_particles.empty()) return 0;
	const std::vector<double> w = normalizedLinearWeights();
	double sum2 = 0;
	for (double x : w) sum2 += x * x;
	return sum2 > 0 ? 1.0 / (static_cast<double>(w.size()) * sum2) : 0;
}

void CVSlamParticleFilter::performSubstitution(const std::vector<size_t>& indx)
{
	CParticleFilterDataImpl::performSubstitution(indx);
	for (auto& p : m_particles) p.log_w = 0;
	m_stats.resamplings++;
}

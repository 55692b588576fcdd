#include <libvslam/config/StrictRead.h>
#include <libvslam/filter/CKidnapDetector.h>

using namespace vslam;
using namespace vslam::config;

void CKidnapDetector::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	enabled = readBool(c, s, "enabled", enabled);
	min_unexplained_frames = static_cast<uint32_t>(readInt(
		c, s, "min_unexplained_frames", min_unexplained_frames,
		Range::closed(1, 1e6)));
	min_distinct_landmarks = static_cast<uint32_t>(readInt(
		c, s, "min_distinct_landmarks", min_distinct_landmarks,
		Range::closed(1, 1e6)));
	single_landmark_frames = static_cast<uint32_t>(readInt(
		c, s, "single_landmark_frames", single_landmark_frames,
		Range::closed(0, 1e6)));
	explained_min_fraction = readDouble(
		c, s, "explained_min_fraction", explained_min_fraction,
		{0, 1, false, true});
	revert_on_contradiction =
		readBool(c, s, "revert_on_contradiction", revert_on_contradiction);
}

void CKidnapDetector::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	c.write(s, "enabled", enabled, 25, 12, "Detect kidnapping and recover with dual particles");
	c.write(s, "min_unexplained_frames", static_cast<int>(min_unexplained_frames), 25, 12,
		"Frames of unexplained anchored measurements that one relocalization hypothesis must explain");
	c.write(s, "min_distinct_landmarks", static_cast<int>(min_distinct_landmarks), 25, 12,
		"... involving at least this many different landmarks");
	c.write(s, "single_landmark_frames", static_cast<int>(single_landmark_frames), 25, 12,
		"... or this many frames of one visual landmark, anchored and not a look-alike (0: never)");
	c.write(s, "explained_min_fraction", explained_min_fraction, 25, 12,
		"Weight fraction of particles whose gate must hold a measurement for it to count as explained");
	c.write(s, "revert_on_contradiction", revert_on_contradiction, 25, 12,
		"Go back to the cloud left at a kidnap when another anchored landmark contradicts the kidnap");
}

CKidnapDetector::Verdict CKidnapDetector::update(
	mrpt::Clock::time_point t, const std::vector<Evidence>& evidence,
	const Context& ctx)
{
	if (!m_verified) m_verified = t;  // landmarks of the first frame anchor
	if (m_hypothesis.active()) m_hypothesis.predict(ctx.motion, ctx.rng);
	if (m_return.active())
	{
		m_return.predict(ctx.motion, ctx.rng);
		if (contradictsKidnap(evidence, ctx))
		{
			m_verified = m_returnAnchor;
			m_localized = true;
			m_hypothesis.clear();
			// The landmarks that confirmed the kidnap told a false story.
			m_lookAlikes.insert(m_kidnapSupport.begin(), m_kidnapSupport.end());
			m_reverts++;
			return Verdict::Reverted;
		}
	}

	std::vector<KnownMeasurement> counted;
	bool anyExplained = false, anyConfirmsAlone = false;
	for (const auto& e : evidence)
	{
		// A young landmark explained is no evidence: it was placed from this belief.
		if (!anchored(e.created) && e.explained) continue;
		counted.push_back(e.measurement);
		anyExplained = anyExplained || e.explained;
		anyConfirmsAlone = anyConfirmsAlone || confirmsAlone(e);
	}
	if (counted.empty()) return Verdict::Neutral;
	if (anyExplained)
	{
		m_verified = t;
		m_localized = true;
		dropHypothesis();
		return Verdict::Localized;
	}
	m_localized = false;
	if (!options.enabled) return Verdict::Unexplained;

	if (m_hypothesis.active() &&
		m_hypothesis.explainedFraction(counted, ctx.likelihood) >= options.explained_min_fraction)
	{
		m_hypothesis.confirm(counted, ctx.likelihood, ctx.rng);
		m_hypothesisConfirmableAlone = m_hypothesisConfirmableAlone || anyConfirmsAlone;
	}
	else
	{
		m_hypothesis.start(
			counted, ctx.bank, ctx.particles, ctx.likelihood, ctx.rng);
		m_hypothesisConfirmableAlone = anyConfirmsAlone;
	}

	const auto& h = m_hypothesis;
	const bool confirmed = h.active() &&
		((h.support() >= options.min_unexplained_frames &&
		  h.distinctLandmarks() >= options.min_distinct_landmarks) ||
		 (options.single_landmark_frames > 0 && m_hypothesisConfirmableAlone &&
		  h.support() >= options.single_landmark_frames));
	if (confirmed)
	{
		m_detections++;
		return Verdict::Kidnapped;
	}
	return Verdict::Unexplained;
}

bool CKidnapDetector::confirmsAlone(const Evidence& e) const
{
	// Young landmarks are placed less surely than anchored ones: one of them
	// alone never confirms a kidnap, two distinct ones may. One point landmark
	// leaves each frame's pose free on a circle around it: only a landmark
	// that measures the whole pose may confirm alone. A look-alike has told
	// a false story before.
	return e.measurement.m->kind() == LandmarkKind::Pose && anchored(e.created) &&
		m_lookAlikes.count(e.measurement.m->key) == 0;
}

void CKidnapDetector::dropHypothesis()
{
	if (m_hypothesis.active() && m_hypothesis.support() >= options.min_unexplained_frames)
		m_lookAlikes.insert(m_hypothesis.landmarks().begin(), m_hypothesis.landmarks().end());
	m_hypothesis.clear();
}

bool CKidnapDetector::contradictsKidnap(
	const std::vector<Evidence>& evidence, const Context& ctx)
{
	std::vector<KnownMeasurement> contradicting;
	for (const auto& e : evidence)
	{
		if (e.created > m_returnAnchor || m_kidnapSupport.count(e.measurement.m->key)) continue;
		if (e.explained)
		{
			m_return.clear();  // an independent landmark confirms the kidnap
			return false;
		}
		contradicting.push_back(e.measurement);
	}
	if (contradicting.empty() ||
		m_return.explainedFraction(contradicting, ctx.likelihood) <
			options.explained_min_fraction)
		return false;
	m_return.confirm(contradicting, ctx.likelihood, ctx.rng);
	return true;
}

void CKidnapDetector::acceptHypothesis(
	const std::vector<se2::Pose>& left, const std::vector<double>& leftLogW,
	const LandmarkBank& leftBank)
{
	m_return.clear();
	if (options.revert_on_contradiction && m_verified)
	{
		m_return.startFrom(left, leftLogW, leftBank);
		m_returnAnchor = *m_verified;
		m_kidnapSupport = m_hypothesis.landmarks();
	}
	m_hypothesis.clear();
}

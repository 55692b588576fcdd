#include <libvslam/frontend/CVisualFrontEnd.h>
#include <libvslam/frontend/LandmarkAppearance.h>
#include <libvslam/frontend/LandmarkRecognizer.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>

using namespace vslam;

namespace
{
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

/** A reason with its numbers replaced by "N", to count reasons. */
std::string withoutNumbers(const std::string& text)
{
	std::string out;
	size_t i = 0;
	while (i < text.size())
	{
		size_t end = i;
		while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) end++;
		if (end == i)
			out += text[i++];
		else
		{
			const bool partOfWord = end < text.size() && text[end] == '-';  // "3-D"
			out += partOfWord ? text.substr(i, end - i) : std::string("N");
			i = end;
		}
	}
	return out;
}

/** A landmark is expected in view when the robot is near where it was
 * built and looks the same way (odometry only: the front-end has no map). */
bool expectedInView(const mrpt::poses::CPose2D& createdAt, const mrpt::poses::CPose2D& now)
{
	constexpr double kNear = 0.5, kSameWay = 20 * M_PI / 180;
	return (now - createdAt).norm() < kNear &&
		std::abs(mrpt::math::wrapToPi(now.phi() - createdAt.phi())) < kSameWay;
}
}  // namespace

CVisualFrontEnd::CVisualFrontEnd(const TOptions& options)
	: m_options(options),
	  m_extractor(options.features),
	  m_database(options.database, options.features.match_ratio),
	  m_creator(options.creator()),
	  m_recognizer(options.recognizer()),
	  m_headingEstimator(options.headingEstimator())
{
}

void CVisualFrontEnd::loadMap(const CVSlamMap& map, const mrpt::poses::CPose2D& worldInOdometry)
{
	std::map<int64_t, mrpt::poses::CPose2D> inWorld;
	for (const auto& e : map.estimates)
		if (e.kind == 0)
		{
			inWorld[e.id] = mrpt::poses::CPose2D(e.mean[0], e.mean[1], e.mean[2]);
			m_nextId = std::max(m_nextId, e.id + 1);  // also for a map without appearances
		}
	const TScaleTrackOptions settings = m_options.scale.settings();
	std::vector<VisualLandmarkModel> landmarks;
	for (const auto& record : map.appearances)
	{
		landmarks.push_back(landmarkOf(record, m_options.scale.enabled ? &settings : nullptr));
		// Where the map has it, not where the old run's odometry had it.
		landmarks.back().createdAtOdometry = worldInOdometry + inWorld.at(record.id);
	}
	m_database.insertStored(std::move(landmarks));
	m_nextId = std::max(m_nextId, map.nextVisualLandmarkId);
}

void CVisualFrontEnd::saveMap(CVSlamMap& map) const
{
	for (const auto& [id, lm] : m_database.landmarks()) map.appearances.push_back(appearanceOf(lm));
	map.descriptorStorage = m_options.database.descriptor_storage;
	map.nextVisualLandmarkId = m_nextId;
	map.hasCamera = m_camera.has_value();
	if (m_camera) map.camera = *m_camera;
}

CVisualFrontEnd::Output CVisualFrontEnd::process(
	const mrpt::obs::CObservationImage& obs, const mrpt::poses::CPose2D& odometryPose, const std::string& what)
{
	Output out;
	m_images++;
	if (m_lastOdometry) m_travelled += (odometryPose - *m_lastOdometry).norm();
	m_lastOdometry = odometryPose;
	CreationView view = viewOf(obs, odometryPose, what, out);
	const Recognitions recognized = recognize(view, obs, odometryPose, out);
	if (!m_mapFixed)
	{
		const auto t = Clock::now();
		collectForCreation(std::move(view), recognized, obs, odometryPose, out);
		out.seconds.creation = since(t);
		prune(odometryPose, recognized.ids, out);
	}

	m_total.features += out.seconds.features;
	m_total.search += out.seconds.search;
	m_total.pose += out.seconds.pose;
	m_total.creation += out.seconds.creation;
	m_total.heading += out.seconds.heading;
	return out;
}

CreationView CVisualFrontEnd::viewOf(
	const mrpt::obs::CObservationImage& obs, const mrpt::poses::CPose2D& odometryPose, const std::string& what, Output& out)
{
	auto t = Clock::now();
	const cv::Mat pixels = obs.image.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	if (pixels.empty()) throw std::runtime_error(what + ": the image is empty or could not be loaded");
	const auto calibration = CImageCalibration::from(obs.cameraParams, pixels.cols, pixels.rows, m_options.camera, what);
	if (!m_camera) m_camera = obs.cameraParams;
	CreationView view;
	view.features = m_extractor.extract(pixels, calibration);
	m_database.encode(view.features);
	view.time = mrpt::Clock::toDouble(obs.timestamp);
	view.cameraPose = mrpt::poses::CPose3D(odometryPose) + obs.cameraPose;
	out.features = view.features.size();
	out.seconds.features = since(t);
	if (m_options.heading.enabled)
	{
		t = Clock::now();
		measureHeadingChange(obs, view.features, odometryPose, out);
		out.seconds.heading = since(t);
	}
	return view;
}

namespace
{
/** The observation the filter receives for a reported recognition. */
CObservationVisualLandmark::Ptr measurementOf(const VisualMeasurement& m, const mrpt::obs::CObservationImage& obs)
{
	auto o = CObservationVisualLandmark::Create();
	o->timestamp = obs.timestamp;
	o->sensorLabel = obs.sensorLabel;
	o->landmarkID = m.landmarkID;
	o->relPose = m.landmarkInRobot;
	o->ProjErrRMS = m.ProjErrRMS;
	o->NPoints = static_cast<uint32_t>(m.NPoints);
	o->Slope = m.Slope;
	o->SlopeStd = m.stdSlope;
	o->Height = m.robotInLandmark.z();
	o->sensorPoseOnRobot = obs.cameraPose;
	o->relPoseCov = mrpt::math::CMatrixDouble33(m.covariance);
	return o;
}
}  // namespace

CVisualFrontEnd::Recognitions CVisualFrontEnd::recognize(const CreationView& view,
	const mrpt::obs::CObservationImage& obs, const mrpt::poses::CPose2D& odometryPose, Output& out)
{
	auto t = Clock::now();
	const auto candidates = m_database.candidates(view.features);
	out.seconds.search = since(t);
	t = Clock::now();
	Recognitions recognized;
	for (const auto& c : candidates)
	{
		VisualLandmarkModel* lm = m_database.find(c.id);
		auto m = m_recognizer.recognize(view.features, *lm, obs.cameraPose);
		if (!m) continue;
		lm->recognitions++;
		lm->missesInARow = 0;
		lm->lastSeen = view.time;
		recognized.ids.push_back(c.id);
		if (!reportable(*lm, *m, view.time, odometryPose)) continue;  // recognized: no new landmark here
		if (m_options.scale.enabled && !m_mapFixed) refineScale(*lm, *m, odometryPose, obs.cameraPose);
		lm->lastReported = ReportedRecognition{view.time, odometryPose.asTPose(), m->landmarkInRobot.asTPose()};
		out.measurements.push_back(measurementOf(*m, obs));
	}
	out.seconds.pose = since(t);
	return recognized;
}

bool CVisualFrontEnd::reportable(
	const VisualLandmarkModel& landmark, const VisualMeasurement& m, double time, const mrpt::poses::CPose2D& odometryPose)
{
	// A degenerate solve measures nothing, ...
	if (!m.covariance.allFinite())
		m_poorlyConditioned++;
	// ... nor one where the odometry since its last recognition does not put it.
	else if (!agreesWithOdometry(
				 landmark.lastReported, time, odometryPose, m.landmarkInRobot, m_options.recognition.odometry_gate))
		m_inconsistent++;
	else
		return true;
	return false;
}

void CVisualFrontEnd::collectForCreation(CreationView view, const Recognitions& recognized,
	const mrpt::obs::CObservationImage& obs, const mrpt::poses::CPose2D& odometryPose, Output& out)
{
	// Views along the robot's motion where no landmark is recognized.
	if (!recognized.ids.empty())
	{
		m_views.clear();
		return;
	}
	const bool moved =
		m_views.empty() || (odometryPose - m_views.back().second).norm() >= m_options.creation.min_baseline;
	if (moved) m_views.emplace_back(std::move(view), odometryPose);
	while (!m_views.empty() &&
		(odometryPose - m_views.front().second).norm() > m_options.creation.max_baseline * (m_options.creation.views - 1))
		m_views.pop_front();
	if (static_cast<int>(m_views.size()) >= m_options.creation.views) createFromViews(obs, odometryPose, out);
}

void CVisualFrontEnd::createFromViews(
	const mrpt::obs::CObservationImage& obs, const mrpt::poses::CPose2D& odometryPose, Output& out)
{
	std::vector<const CreationView*> ptrs;
	double baseline = 0;
	for (size_t i = m_views.size() - m_options.creation.views; i < m_views.size(); i++)
	{
		ptrs.push_back(&m_views[i].first);
		if (ptrs.size() > 1) baseline += (m_views[i].second - m_views[i - 1].second).norm();
	}
	auto result = m_creator.create(ptrs, obs.cameraPose);
	m_creationAttempts++;
	if (!result.landmark)
	{
		m_creationRejections[withoutNumbers(result.why)]++;
		m_views.pop_front();  // try again with a newer set
		return;
	}
	result.landmark->id = m_nextId++;
	auto c = CObservationLandmarkCreated::Create();
	c->timestamp = obs.timestamp;
	c->sensorLabel = obs.sensorLabel;
	c->landmarkID = result.landmark->id;
	// The landmark frame is the robot frame of this image.
	c->landmarkPoseInRobot = mrpt::poses::CPose2D();
	c->landmarkPoseInRobotCov = mrpt::math::CMatrixDouble33::Zero();
	c->NPoints = static_cast<uint32_t>(result.landmark->points.size());
	c->NViews = static_cast<uint32_t>(result.landmark->views);
	c->sensorPoseOnRobot = obs.cameraPose;
	out.created.push_back(c);
	result.landmark->createdAtOdometry = odometryPose;
	if (m_options.scale.enabled) result.landmark->scale = CLandmarkScaleTrack(baseline, m_options.scale.settings());
	m_database.insert(std::move(*result.landmark));
	m_views.clear();
}

void CVisualFrontEnd::measureHeadingChange(const mrpt::obs::CObservationImage& obs,
	const ImageFeatures& features, const mrpt::poses::CPose2D& odometryPose, Output& out)
{
	PreviousImage current{features, odometryPose, obs.timestamp};
	const auto previous = m_previousImage.find(obs.sensorLabel);
	if (previous != m_previousImage.end() && previous->second.timestamp < obs.timestamp)
	{
		// Backwards (odometry's sign): the chord's direction stays near the heading.
		const mrpt::poses::CPose2D moved = odometryPose - previous->second.odometryPose;
		const double chord = moved.x() >= 0 ? moved.norm() : -moved.norm();
		const auto e = m_headingEstimator.estimate(previous->second.features, features, obs.cameraPose, chord);
		if (e)
		{
			auto h = CObservationHeadingChange::Create();
			h->timestamp = obs.timestamp;
			h->sensorLabel = obs.sensorLabel + "_HEADING";
			h->previousTimestamp = previous->second.timestamp;
			h->dphi = e->dphi;
			h->stdDphi = e->stdDphi;
			h->NMatches = static_cast<uint32_t>(e->matches);
			h->NInliers = static_cast<uint32_t>(e->inliers);
			h->rmsPx = e->rmsPx;
			h->sensorPoseOnRobot = obs.cameraPose;
			out.headingChanges.push_back(h);
			m_headingChangesMeasured++;
		}
		else
			m_headingChangesFailed++;
	}
	m_previousImage[obs.sensorLabel] = std::move(current);
}

void CVisualFrontEnd::refineScale(VisualLandmarkModel& lm, VisualMeasurement& m,
	const mrpt::poses::CPose2D& odometryPose, const mrpt::poses::CPose3D& mount)
{
	const mrpt::poses::CPose3D cameraInLandmark = m.robotInLandmark + mount;
	const mrpt::poses::CPose3D cameraInOdometry = mrpt::poses::CPose3D(odometryPose) + mount;
	ScaleSighting s;
	s.cameraInLandmark = {cameraInLandmark.x(), cameraInLandmark.y()};
	s.headingInLandmark = m.robotInLandmark.yaw();
	s.stdPosition = m.stdPosition;  // the solve's position std (of the landmark in the robot frame)
	s.cameraInOdometry = {cameraInOdometry.x(), cameraInOdometry.y()};
	s.headingInOdometry = odometryPose.phi();
	s.travelled = m_travelled;
	const double factor = lm.scale.addSighting(s);
	if (factor == 1) return;
	for (auto& p : lm.points) p *= factor;
	// The landmark's lengths changed, so did the camera's position in its
	// frame; the robot's follows through the mount (in metres).
	const mrpt::poses::CPose3D rescaledCamera(factor * cameraInLandmark.x(), factor * cameraInLandmark.y(),
		factor * cameraInLandmark.z(), cameraInLandmark.yaw(), cameraInLandmark.pitch(), cameraInLandmark.roll());
	m.robotInLandmark = rescaledCamera + (mrpt::poses::CPose3D() - mount);
	m.landmarkInRobot = mrpt::poses::CPose2D() -
		mrpt::poses::CPose2D(m.robotInLandmark.x(), m.robotInLandmark.y(), m.robotInLandmark.yaw());
}

void CVisualFrontEnd::prune(
	const mrpt::poses::CPose2D& odometryPose, const std::vector<int64_t>& recognized, Output& out)
{
	std::vector<int64_t> remove;
	if (m_options.database.prune_after_misses > 0)
		for (const auto& [id, lm] : m_database.landmarks())
		{
			if (std::find(recognized.begin(), recognized.end(), id) != recognized.end()) continue;
			if (!expectedInView(lm.createdAtOdometry, odometryPose)) continue;
			auto* l = m_database.find(id);
			if (++l->missesInARow >= m_options.database.prune_after_misses) remove.push_back(id);
		}
	if (m_options.database.max_landmarks > 0 &&
		static_cast<int>(m_database.size() - remove.size()) > m_options.database.max_landmarks)
	{
		// Over the cap: the longest unseen go first (a new landmark counts as
		// seen now), among equals the least recognized.
		std::vector<std::pair<std::pair<double, int>, int64_t>> rank;
		for (const auto& [id, lm] : m_database.landmarks())
			if (std::find(remove.begin(), remove.end(), id) == remove.end())
				rank.push_back({{lm.lastSeen, lm.recognitions}, id});
		std::sort(rank.begin(), rank.end());
		const size_t excess = m_database.size() - remove.size() - static_cast<size_t>(m_options.database.max_landmarks);
		for (size_t i = 0; i < excess; i++) remove.push_back(rank[i].second);
	}
	for (int64_t id : remove)
	{
		m_database.remove(id);
		out.pruned.push_back(id);
	}
}

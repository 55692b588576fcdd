#include <libvslam/app/RunSummary.h>
#include <libvslam/core/ExceptionText.h>
#include <libvslam/core/InputError.h>
#include <libvslam/io/COutputFile.h>
#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace vslam
{
double peakMemoryMiB()
{
	struct rusage u;
	getrusage(RUSAGE_SELF, &u);
	return static_cast<double>(u.ru_maxrss) / 1024.0;  // ru_maxrss is KiB
}

namespace
{
using mrpt::containers::yaml;

/** A YAML double-quoted scalar of any bytes. MRPT's emitter writes strings
 * bare, so text from outside (file names, MRPT's error messages with raw
 * bytes) is quoted here: quotes and backslashes escaped, every byte outside
 * printable ASCII as \xNN. */
std::string quotedText(const std::string& s)
{
	std::string out = "\"";
	for (const unsigned char c : s)
	{
		if (c == '"' || c == '\\')
			out += '\\', out += static_cast<char>(c);
		else if (c >= 0x20 && c < 0x7f)
			out += static_cast<char>(c);
		else
		{
			char hex[8];
			std::snprintf(hex, sizeof hex, "\\x%02x", c);
			out += hex;
		}
	}
	return out + "\"";
}

/** A number, or null when it is not finite (YAML readers disagree on NaN). */
yaml number(double v) { return std::isfinite(v) ? yaml(v) : yaml(); }

/** Error figures, or null over no associated pose. */
yaml ateNode(const std::optional<AteStats>& a)
{
	if (!a || a->associated == 0) return yaml();
	yaml n = yaml::Map();
	n["associated_poses"] = static_cast<uint64_t>(a->associated);
	n["rmse"] = number(a->rmse);
	n["mean"] = number(a->mean);
	n["median"] = number(a->median);
	n["max"] = number(a->max);
	n["heading_rmse_deg"] = number(a->headingRmse * 180 / M_PI);
	return n;
}

yaml measurementsNode(const CVSlamParticleFilter& f)
{
	const auto& ex = f.extractor().stats();
	yaml m = yaml::Map();
	m["visual_seen"] = ex.visualSeen;
	m["visual_accepted_by_prefilter"] = ex.visualAccepted;
	m["range_bearing_seen"] = ex.rangeBearingSeen;
	m["range_bearing_accepted"] = ex.rangeBearingAccepted;
	m["heading_changes_seen"] = ex.headingChangesSeen;
	m["heading_changes_passed"] = ex.headingChangesPassed;
	m["used_by_filter"] = f.stats().measurementsUsed;
	yaml r = yaml::Map();
	r["prefilter_ProjErrRMS"] = ex.rejectedProjErrRMS;
	r["prefilter_NPoints"] = ex.rejectedNPoints;
	r["prefilter_Slope"] = ex.rejectedSlope;
	r["no_landmark_id"] = ex.rejectedNoLandmarkID;
	r["range_limits"] = ex.rejectedRangeLimits;
	r["unexplained_by_any_particle"] = f.stats().rejectedUnexplained;
	m["rejected"] = r;
	return m;
}

yaml filterNode(const CVSlamParticleFilter& f)
{
	const auto& fs = f.stats();
	yaml n = yaml::Map();
	n["frames"] = fs.frames;
	n["resamplings"] = fs.resamplings;
	n["dual_particles_drawn"] = fs.dualParticlesDrawn;
	n["unexplained_frames"] = fs.unexplainedFrames;
	n["kidnaps_detected"] = fs.kidnapsDetected;
	n["kidnaps_reverted"] = fs.kidnapsReverted;
	n["look_alike_landmarks"] = f.kidnapDetector().lookAlikes();
	n["loop_closures"] = fs.loopClosures;
	n["loop_closure_edges_left_out"] = fs.loopClosureEdgesLeftOut;
	yaml h = yaml::Map();
	h["fused"] = fs.headingChangesFused;
	h["gated"] = fs.headingChangesGated;
	h["without_reference"] = fs.headingChangesWithoutReference;
	n["heading_changes"] = h;
	return n;
}

yaml landmarksNode(const CVSlamParticleFilter& f)
{
	uint64_t pose = 0, point = 0, neverSeenAgain = 0;
	for (size_t i = 0; i < f.landmarkIndex().size(); i++)
	{
		const auto& entry = f.landmarkIndex().entry(i);
		(entry.key.kind == LandmarkKind::Pose ? pose : point)++;
		// Placed, and never measured after: an ID that did not repeat.
		if (entry.measurements == 0) neverSeenAgain++;
	}
	yaml n = yaml::Map();
	n["total"] = static_cast<uint64_t>(f.landmarkIndex().size());
	n["pose"] = pose;
	n["point"] = point;
	n["never_seen_again"] = neverSeenAgain;
	const auto& ex = f.extractor().stats();
	const auto& fs = f.stats();
	yaml e = yaml::Map();
	e["creations_seen"] = ex.creationsSeen;
	e["created"] = fs.landmarksCreated;
	e["created_at_first_sighting"] = fs.landmarksCreatedFromMeasurement;
	e["reinitialized"] = fs.landmarksReinitialized;
	e["duplicate_creations"] = fs.duplicateCreations;
	e["not_placed"] = fs.landmarksNotPlaced;
	n["events"] = e;
	n["map_fixed"] = f.mapFixed();
	return n;
}

yaml frontEndNode(const RunSummary::FrontEnd& e)
{
	const auto perImage = [&](double seconds) { return e.images ? 1000 * seconds / e.images : 0.0; };
	yaml n = yaml::Map();
	n["images"] = e.images;
	n["measurements"] = e.measurements;
	n["landmarks_created"] = e.created;
	n["landmarks_pruned"] = e.pruned;
	n["landmarks_in_database"] = e.landmarks;
	n["bytes_per_landmark"] = e.bytesPerLandmark;
	n["index_bytes"] = e.indexBytes;
	yaml ms = yaml::Map();
	ms["features"] = perImage(e.featuresSeconds);
	ms["search"] = perImage(e.searchSeconds);
	ms["pose"] = perImage(e.poseSeconds);
	ms["creation"] = perImage(e.creationSeconds);
	ms["heading_change"] = perImage(e.headingSeconds);
	n["ms_per_image"] = ms;
	yaml h = yaml::Map();
	h["measured"] = e.headingChanges;
	h["failed"] = e.headingChangesFailed;
	n["heading_changes"] = h;
	yaml r = yaml::Map();
	r["poorly_conditioned"] = e.poorlyConditioned;
	r["inconsistent"] = e.inconsistent;
	n["recognitions_not_reported"] = r;
	n["creation_attempts"] = e.creationAttempts;
	yaml why;  // null when empty: MRPT cannot read back an empty map
	if (!e.creationRejections.empty()) why = yaml::Map();
	for (const auto& [reason, count] : e.creationRejections) why[quotedText(reason)] = count;
	n["creation_rejected"] = why;
	return n;
}
}  // namespace

double RunSummary::speedUp() const
{
	return totalSeconds > 0 ? realTimeSpan / totalSeconds : 0.0;
}

mrpt::containers::yaml RunSummary::toYaml(const CVSlamParticleFilter* f) const
{
	yaml y = yaml::Map();
	y["status"] = status;
	if (!error.empty()) y["error"] = quotedText(error);
	y["run_id"] = quotedText(runId);
	y["config_file"] = quotedText(configFile);
	y["rawlog_file"] = quotedText(rawlogFile);
	y["output_dir"] = quotedText(outputDir);
	y["random_seed"] = seed;
	if (!f) return y;  // the start of a run
	yaml r = yaml::Map();
	r["steps"] = steps;
	r["action_sensoryframe_steps"] = actionFrameSteps;
	r["observation_steps"] = observationSteps;
	r["skipped_objects"] = skippedObjects;
	r["data_seconds"] = realTimeSpan > 0 ? yaml(realTimeSpan) : yaml();
	r["longest_gap_seconds"] = realTimeSpan > 0 ? yaml(longestGap) : yaml();
	y["rawlog"] = r;
	y["particles"] = static_cast<uint64_t>(f->particlesCount());
	y["landmarks"] = landmarksNode(*f);
	y["measurements"] = measurementsNode(*f);
	y["filter"] = filterNode(*f);
	yaml t = yaml::Map();
	t["total_seconds"] = totalSeconds;
	t["step_mean_ms"] = stepMeanMs;
	t["step_max_ms"] = stepMaxMs;
	t["faster_than_real_time"] = speedUp() > 0 ? yaml(speedUp()) : yaml();
	y["timing"] = t;
	y["peak_memory_MiB"] = peakMemoryMiB;
	if (frontEnd) y["front_end"] = frontEndNode(*frontEnd);
	if (startPose)
	{
		yaml p = yaml::Map();
		const auto seconds = [](const std::optional<double>& v) { return v ? yaml(*v) : yaml(); };
		p["steps_with_unknown_pose"] = startPose->unknownSteps;
		p["first_mapped_landmark_measured_at_s"] = seconds(startPose->firstMappedSightingAt);
		p["found_at_s"] = seconds(startPose->foundAt);
		p["measurements_while_unknown"] = f->stats().measurementsWhilePoseUnknown;
		y["unknown_start_pose"] = p;
	}
	if (ate || odometryAte)
	{
		yaml e = yaml::Map();
		e["ground_truth_cover"] = number(groundTruthCover);
		if (!groundTruthWarning.empty()) e["warning"] = quotedText(groundTruthWarning);
		e["vslam"] = ateNode(ate);
		e["vslam_se2_aligned"] = ateNode(ateAligned);
		e["most_likely_path"] = ateNode(smoothedAte);
		e["most_likely_path_se2_aligned"] = ateNode(smoothedAteAligned);
		e["pose_graph_path"] = ateNode(poseGraphAte);
		e["dead_reckoning"] = ateNode(odometryAte);
		y["error_vs_ground_truth_m"] = e;
	}
	return y;
}

void RunSummary::write(const std::string& file, const CVSlamParticleFilter* f) const
{
	std::ostringstream o;
	o << "# vslam run summary\n";
	toYaml(f).printAsYAML(o);
	COutputFile out(file, COutputFile::Mode::Atomic);
	out.write(o.str());
	out.commit();
}

mrpt::containers::yaml readRunSummary(const std::string& file)
{
	std::ifstream in(file);
	if (!in) throw InputError("cannot read run summary '" + file + "'");
	try
	{
		return yaml::FromStream(in);
	}
	catch (const std::exception& e)
	{
		throw InputError("run summary '" + file + "' is not valid YAML: " + exceptionText(e));
	}
}

double summaryNumber(const mrpt::containers::yaml& node, const std::string& path)
{
	if (path.empty())
	{
		if (!node.isScalar()) return NAN;
		try
		{
			return node.as<double>();
		}
		catch (const std::exception&)
		{
			return NAN;  // not a number
		}
	}
	const auto dot = path.find('.');
	const std::string key = path.substr(0, dot);
	if (!node.isMap() || !node.has(key)) return NAN;
	return summaryNumber(node[key], dot == std::string::npos ? "" : path.substr(dot + 1));
}

std::string RunSummary::brief(const CVSlamParticleFilter& f) const
{
	std::ostringstream o;
	o.precision(4);
	o << "vslam: " << status << ": " << steps << " steps, " << f.landmarkIndex().size()
	  << " landmarks, " << f.stats().measurementsUsed << " measurements used, "
	  << f.stats().kidnapsDetected << " kidnaps detected (" << f.stats().kidnapsReverted
	  << " reverted), " << totalSeconds << " s for "
	  << realTimeSpan << " s of data (" << speedUp() << "x real time), peak memory "
	  << peakMemoryMiB << " MiB\n";
	if (ate && ate->associated == 0) o << "vslam: ATE vs ground truth: no step has a ground-truth pose\n";
	if (ate && ate->associated > 0)
		o << "vslam: ATE vs ground truth: RMSE " << ate->rmse << " m, mean " << ate->mean
		  << " m, median " << ate->median << " m, max " << ate->max << " m ("
		  << ate->associated << " poses)\n";
	if (odometryAte && odometryAte->associated > 0)
		o << "vslam: dead reckoning:      RMSE " << odometryAte->rmse << " m, mean "
		  << odometryAte->mean << " m, median " << odometryAte->median << " m\n";
	return o.str();
}
}  // namespace vslam

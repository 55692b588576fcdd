#include <libvslam/app/RunSummary.h>
#include <libvslam/core/InputError.h>
#include <sys/resource.h>

#include <cstdio>
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
/** YAML double-quoted scalar. */
std::string quoted(const std::string& s)
{
	std::string out = "\"";
	for (char c : s)
	{
		if (c == '"' || c == '\\') out += '\\';
		if (c == '\n')
		{
			out += "\\n";
			continue;
		}
		out += c;
	}
	return out + "\"";
}

/** A real-time figure, or null when the rawlog's timestamps give none. */
std::string realTime(double v)
{
	if (!(v > 0)) return "null";
	std::ostringstream o;
	o << v;
	return o.str();
}

void writeAte(std::ostream& o, const char* name, const std::optional<AteStats>& a)
{
	if (!a) return;
	o << "  " << name << ": {associated_poses: " << a->associated << ", rmse: " << a->rmse
	  << ", mean: " << a->mean << ", median: " << a->median << ", max: " << a->max
	  << ", heading_rmse_deg: " << a->headingRmse * 180 / M_PI << "}\n";
}
}  // namespace

double RunSummary::speedUp() const
{
	return totalSeconds > 0 ? realTimeSpan / totalSeconds : 0.0;
}

void RunSummary::write(const std::string& file, const CVSlamParticleFilter& f) const
{
	const auto& fs = f.stats();
	const auto& ex = f.extractor().stats();
	size_t pose = 0, point = 0;
	for (size_t i = 0; i < f.landmarkIndex().size(); i++)
		(f.landmarkIndex().entry(i).key.kind == LandmarkKind::Pose ? pose : point)++;
	std::ostringstream o;
	o << "# vslam run summary\n"
	  << "status: " << status << "\n";
	if (!error.empty()) o << "error: " << quoted(error) << "\n";
	o << "config_file: " << quoted(configFile) << "\n"
	  << "rawlog_file: " << quoted(rawlogFile) << "\n"
	  << "output_dir: " << quoted(outputDir) << "\n"
	  << "random_seed: " << seed << "\n"
	  << "rawlog:\n"
	  << "  steps: " << steps << "\n"
	  << "  action_sensoryframe_steps: " << actionFrameSteps << "\n"
	  << "  observation_steps: " << observationSteps << "\n"
	  << "  skipped_objects: " << skippedObjects << "\n"
	  << "  data_seconds: " << realTime(realTimeSpan) << "\n"
	  << "particles: " << f.particlesCount() << "\n"
	  << "landmarks: {total: " << f.landmarkIndex().size() << ", pose: " << pose
	  << ", point: " << point << "}\n"
	  << "measurements:\n"
	  << "  visual_seen: " << ex.visualSeen << "\n"
	  << "  visual_accepted_by_prefilter: " << ex.visualAccepted << "\n"
	  << "  range_bearing_seen: " << ex.rangeBearingSeen << "\n"
	  << "  range_bearing_accepted: " << ex.rangeBearingAccepted << "\n"
	  << "  heading_changes_seen: " << ex.headingChangesSeen << "\n"
	  << "  heading_changes_passed: " << ex.headingChangesPassed << "\n"
	  << "  used_by_filter: " << fs.measurementsUsed << "\n"
	  << "  rejected:\n"
	  << "    prefilter_ProjErrRMS: " << ex.rejectedProjErrRMS << "\n"
	  << "    prefilter_NPoints: " << ex.rejectedNPoints << "\n"
	  << "    prefilter_Slope: " << ex.rejectedSlope << "\n"
	  << "    no_landmark_id: " << ex.rejectedNoLandmarkID << "\n"
	  << "    range_limits: " << ex.rejectedRangeLimits << "\n"
	  << "    unexplained_by_any_particle: " << fs.rejectedUnexplained << "\n"
	  << "landmark_events:\n"
	  << "  creations_seen: " << ex.creationsSeen << "\n"
	  << "  created: " << fs.landmarksCreated << "\n"
	  << "  created_at_first_sighting: " << fs.landmarksCreatedFromMeasurement << "\n"
	  << "  reinitialized: " << fs.landmarksReinitialized << "\n"
	  << "  duplicate_creations: " << fs.duplicateCreations << "\n"
	  << "filter:\n"
	  << "  frames: " << fs.frames << "\n"
	  << "  resamplings: " << fs.resamplings << "\n"
	  << "  dual_particles_drawn: " << fs.dualParticlesDrawn << "\n"
	  << "  unexplained_frames: " << fs.unexplainedFrames << "\n"
	  << "  kidnaps_detected: " << fs.kidnapsDetected << "\n"
	  << "  kidnaps_reverted: " << fs.kidnapsReverted << "\n"
	  << "  loop_closures: " << fs.loopClosures << "\n"
	  << "  loop_closure_edges_left_out: " << fs.loopClosureEdgesLeftOut << "\n"
	  << "  heading_changes: {fused: " << fs.headingChangesFused << ", gated: " << fs.headingChangesGated
	  << ", without_reference: " << fs.headingChangesWithoutReference << "}\n"
	  << "timing:\n"
	  << "  total_seconds: " << totalSeconds << "\n"
	  << "  step_mean_ms: " << stepMeanMs << "\n"
	  << "  step_max_ms: " << stepMaxMs << "\n"
	  << "  faster_than_real_time: " << realTime(speedUp()) << "\n"
	  << "peak_memory_MiB: " << peakMemoryMiB << "\n";
	if (frontEnd)
	{
		const auto& e = *frontEnd;
		const auto perImage = [&](double seconds) { return e.images ? 1000 * seconds / e.images : 0.0; };
		o << "front_end:\n"
		  << "  images: " << e.images << "\n"
		  << "  measurements: " << e.measurements << "\n"
		  << "  landmarks_created: " << e.created << "\n"
		  << "  landmarks_pruned: " << e.pruned << "\n"
		  << "  landmarks_in_database: " << e.landmarks << "\n"
		  << "  bytes_per_landmark: " << e.bytesPerLandmark << "\n"
		  << "  index_bytes: " << e.indexBytes << "\n"
		  << "  ms_per_image: {features: " << perImage(e.featuresSeconds) << ", search: "
		  << perImage(e.searchSeconds) << ", pose: " << perImage(e.poseSeconds)
		  << ", creation: " << perImage(e.creationSeconds) << ", heading_change: " << perImage(e.headingSeconds) << "}\n"
		  << "  heading_changes: {measured: " << e.headingChanges << ", failed: " << e.headingChangesFailed << "}\n"
		  << "  recognitions_not_reported: {poorly_conditioned: " << e.poorlyConditioned
		  << ", ambiguous: " << e.ambiguous << ", narrow: " << e.narrow
		  << ", inconsistent: " << e.inconsistent << "}\n"
		  << "  creation_attempts: " << e.creationAttempts << "\n"
		  << "  creation_rejected:";
		if (e.creationRejections.empty()) o << " {}";
		o << "\n";
		for (const auto& [why, count] : e.creationRejections) o << "    \"" << why << "\": " << count << "\n";
	}
	if (ate || odometryAte)
	{
		o << "error_vs_ground_truth_m:\n";
		writeAte(o, "vslam", ate);
		writeAte(o, "vslam_se2_aligned", ateAligned);
		writeAte(o, "most_likely_path", smoothedAte);
		writeAte(o, "most_likely_path_se2_aligned", smoothedAteAligned);
		writeAte(o, "pose_graph_path", poseGraphAte);
		writeAte(o, "dead_reckoning", odometryAte);
	}
	FILE* out = std::fopen(file.c_str(), "wt");
	if (!out) throw InputError("cannot create output file '" + file + "'");
	std::fputs(o.str().c_str(), out);
	std::fclose(out);
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
	if (ate)
		o << "vslam: ATE vs ground truth: RMSE " << ate->rmse << " m, mean " << ate->mean
		  << " m, median " << ate->median << " m, max " << ate->max << " m ("
		  << ate->associated << " poses)\n";
	if (odometryAte)
		o << "vslam: dead reckoning:      RMSE " << odometryAte->rmse << " m, mean "
		  << odometryAte->mean << " m, median " << odometryAte->median << " m\n";
	return o.str();
}
}  // namespace vslam

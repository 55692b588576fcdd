#pragma once
/** \file RunSummary.h
 * The run summary (run_summary.yaml): what was processed, what was
 * accepted and rejected by which rule, kidnaps, timing, memory, and errors
 * against ground truth when given. Built and read as an
 * mrpt::containers::yaml document, text from outside (file names, error
 * messages) quoted and escaped, so any YAML reader parses it; written
 * atomically. An error figure over no pose is null, never 0. */
#include <libvslam/eval/AbsoluteTrajectoryError.h>
#include <libvslam/filter/CVSlamParticleFilter.h>
#include <mrpt/containers/yaml.h>

#include <map>
#include <optional>
#include <string>

namespace vslam
{
struct RunSummary
{
	std::string status = "running";  //!< running | completed | interrupted | failed
	std::string error;  //!< when failed
	std::string runId;  //!< also in the header of the output files
	std::string configFile, rawlogFile, outputDir;
	/** Share of the run's steps the ground truth covers (when given), and
	 * what the user should know about it (partial cover, odometry that
	 * disagrees with it). */
	double groundTruthCover = 0;
	std::string groundTruthWarning;
	uint64_t seed = 0;
	uint64_t steps = 0, actionFrameSteps = 0, observationSteps = 0, skippedObjects = 0;
	double totalSeconds = 0, stepMeanMs = 0, stepMaxMs = 0;
	double peakMemoryMiB = 0;
	double realTimeSpan = 0;  //!< seconds of data processed (timestamps; 0: unknown)
	double longestGap = 0;  //!< longest time between two consecutive timed steps, s
	std::optional<AteStats> ate, ateAligned, odometryAte;
	/** The best particle's whole path at the end (most_likely_path.tum):
	 * the path smoothed by resampling, raw and SE(2)-aligned. */
	std::optional<AteStats> smoothedAte, smoothedAteAligned;
	/** The loop-closure graph's keyframe path at the end (pose_graph_path.tum). */
	std::optional<AteStats> poseGraphAte;

	/** Global localization (initial_pose_unknown): steps before the pose
	 * was found, when it was found and when a mapped landmark was first
	 * measured (seconds from the first step). */
	struct StartPose
	{
		uint64_t unknownSteps = 0;
		std::optional<double> foundAt, firstMappedSightingAt;
	};
	std::optional<StartPose> startPose;

	/** The visual front-end, when the rawlog had camera images. */
	struct FrontEnd
	{
		size_t images = 0, measurements = 0, created = 0, pruned = 0, landmarks = 0;
		double featuresSeconds = 0, searchSeconds = 0, poseSeconds = 0, creationSeconds = 0, headingSeconds = 0;
		/** Heading changes between images measured, and image pairs without one. */
		size_t headingChanges = 0, headingChangesFailed = 0;
		double bytesPerLandmark = 0, indexBytes = 0;
		size_t creationAttempts = 0;
		std::map<std::string, size_t> creationRejections;  //!< by reason
		/** Recognitions not reported: degenerate, and inconsistent with the
		 * odometry (recognition_odometry_gate_s). */
		size_t poorlyConditioned = 0, inconsistent = 0;
	};
	std::optional<FrontEnd> frontEnd;

	/** Data seconds per processing second (0: unknown). */
	double speedUp() const;
	/** The summary as a document; with the filter's counters if given (none
	 * yet at the start of a run). */
	mrpt::containers::yaml toYaml(const CVSlamParticleFilter* filter) const;
	/** Writes toYaml() atomically; throws OutputError. */
	void write(const std::string& file, const CVSlamParticleFilter* filter) const;
	/** A few human-readable lines for the console. */
	std::string brief(const CVSlamParticleFilter& filter) const;
};

/** Reads a run_summary.yaml; throws InputError naming the file if it is
 * missing or not YAML. */
mrpt::containers::yaml readRunSummary(const std::string& file);

/** A number at a dotted path of a summary ("filter.kidnaps_detected"), or
 * NaN if absent or null. */
double summaryNumber(const mrpt::containers::yaml& summary, const std::string& path);

/** Peak resident memory of this process so far (MiB). */
double peakMemoryMiB();
}  // namespace vslam

#pragma once
/** \file MrclamImporter.h
 * One robot of an UTIAS MRCLAM data set (Leung et al., IJRR 2011) as MRPT
 * data, in the spirit of MRPT's carmen2rawlog:
 *  - one (action, sensory frame) step per image (detections sharing a
 *    timestamp), plus odometry-only steps so no two steps are more than
 *    `max_step_gap` apart;
 *  - the action holds the odometry increment since the previous step,
 *    integrated exactly (circular arcs) from the (v, omega) rows, each row
 *    held until the next one;
 *  - the frame holds a CObservationBearingRange with landmark IDs = MRCLAM
 *    subject numbers (6..20), empty between images (MRPT's kf-slam needs
 *    one in every frame). Barcodes missing from Barcodes.dat (false
 *    detections) and sightings of the other robots (subjects 1..5) are
 *    dropped.
 * Start: the first image with a landmark detection (first step, zero
 * increment). Data is expressed in the frame of the robot's ground-truth
 * pose then (interpolated), so estimate and ground truth both start at the
 * robot's first pose, (0, 0, 0); ground truth and landmark positions are
 * transformed into that frame and the world start pose is reported.
 * (Starting at the first odometry reading instead hands MRPT's kf-slam a
 * wrong heading: it ignores odometry until its map holds a landmark, and
 * some robots turn before their first detection.)
 */
#include <libvslam/io/RawlogWriting.h>
#include <libvslam/io/Trajectory.h>
#include <libvslam/models/CMotionModel.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace vslam
{
struct TMrclamImportOptions
{
	int robot = 1;
	/** Longest time between two steps (s): odometry-only steps fill gaps. */
	double max_step_gap = 0.25;
	/** The robots move this long after their odometry rows say so (the
	 * rows look like commanded twist): odometry row times are shifted by it.
	 * Unset: estimated from the robot's own landmark sightings
	 * (OdometryDelay.h), with no ground truth; 0 keeps the file's times. */
	std::optional<double> odometry_delay;  //!< s
	/** Sensor noise written into each observation (dataset README: robust
	 * std 0.13 m and 0.009 rad). */
	double std_range = 0.15;  //!< m
	double std_bearing = 1.0 * M_PI / 180;  //!< rad
	/** Noise model of the odometry increments: their covariance is written
	 * into each action (kf-slam and rbpf-slam take their motion noise from
	 * it). Defaults: characterized on robot 1's odometry. */
	CMotionModel::TOptions motion = defaultMotion();

	static CMotionModel::TOptions defaultMotion()
	{
		CMotionModel::TOptions m;
		m.sigma_T = 0.08;
		m.sigma_R = 0.1;
		m.sigma_R_per_meter = 0.1;
		return m;
	}
};

struct MrclamLandmark
{
	int subject = 0;
	double x = 0, y = 0;  //!< in the start frame
};

struct MrclamImport
{
	std::vector<ActionFramePair> steps;
	Trajectory groundTruth;  //!< start frame
	std::vector<MrclamLandmark> landmarks;  //!< start frame
	se2::Pose startPoseWorld;
	size_t odometryRows = 0, measurementRows = 0, measurementsUsed = 0;
	size_t droppedFalseBarcodes = 0, droppedRobotSightings = 0, droppedOutsideOdometry = 0;
	double odometryDelay = 0;  //!< s, the shift applied to the odometry rows
	bool odometryDelayEstimated = false;  //!< from the sightings (else given, or 0 for too few)
};

/** Reads `<dir>/Barcodes.dat`, `Landmark_Groundtruth.dat` and
 * `Robot<N>_{Odometry,Measurement,Groundtruth}.dat`. Throws InputError
 * naming the file and line on bad input. */
MrclamImport importMrclam(const std::string& datasetDir, const TMrclamImportOptions& options);

/** Writes "<subject> <x> <y>" rows with a '%' header. */
void writeMrclamLandmarks(const std::string& file, const std::vector<MrclamLandmark>& landmarks);
}  // namespace vslam

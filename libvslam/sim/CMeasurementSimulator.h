#pragma once
/** \file CMeasurementSimulator.h
 * A measurement-level simulator: a robot drives through a room (scripted
 * waypoints or random goals) with noisy, biased odometry; the visual
 * front-end is simulated by its outputs (landmark creations and visual
 * measurements with the paper's ProjErrRMS / NPoints / Slope statistics,
 * bad measurements for the pre-filter, optional false recognitions), or
 * range-bearing measurements of point landmarks. Kidnap events move the
 * robot unseen by odometry. Deterministic for a given seed; it uses its
 * own random generator, never the global one.
 *
 * The output is MRPT data in the action/sensory-frame form, ready for
 * CParticleFilter::executeOn or for a rawlog file, plus ground truth.
 */
#include <libvslam/config/Overrides.h>
#include <libvslam/models/LandmarkTypes.h>
#include <libvslam/models/SE2.h>
#include <libvslam/sim/OdometryErrorModel.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/Clock.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <cstdint>
#include <string>
#include <vector>

namespace vslam
{
struct SimulatedStep
{
	mrpt::Clock::time_point t{};
	se2::Pose truePose{0, 0, 0};  //!< at t, after this step's motion
	se2::Pose odometryIncrement{0, 0, 0};  //!< as measured
	mrpt::obs::CActionCollection::Ptr action;
	mrpt::obs::CSensoryFrame::Ptr sf;  //!< may hold no observation
	bool kidnappedHere = false;
};

struct SimulatedLandmark
{
	LandmarkKey key;
	/** True landmark frame (visual: including the front-end's
	 * reconstruction error) or point (range-bearing: phi = 0). */
	se2::Pose pose;
	/** Built during the unrecorded mapping phase (a prior map holds it). */
	bool mappedBeforeRecording = false;
};

struct SimulatedRun
{
	std::vector<SimulatedStep> steps;
	std::vector<SimulatedLandmark> landmarks;
	size_t visualMeasurements = 0, badMeasurements = 0, falseRecognitions = 0;
	size_t rangeBearingMeasurements = 0, creations = 0;
};

class CMeasurementSimulator
{
   public:
	/** Options of the measurement-level simulator (INI section [vslam_sim]): a robot drives through a rectangular room; the "front-end" is simulated at the level of its outputs (landmark creations and visual measurements with the paper's statistics, or range-bearing to point landmarks). */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		static constexpr const char* kSection = "vslam_sim";

		enum class PathType : uint8_t { Waypoints = 0, Random = 1 };
		enum class LandmarkType : uint8_t { Visual = 0, RangeBearing = 1 };

		uint32_t seed = 1;
		/** Time the robot drives before the recorded run starts: the front-end
		 * builds its landmarks then (they are listed in the ground truth but
		 * not announced in the rawlog), as when continuing from a map. */
		double mapping_duration = 0;  //!< s
		double duration = 300;  //!< s, recorded
		double dt = 0.1;  //!< odometry period, s
		double speed = 0.15;  //!< m/s (paper: about 15 cm/s)
		double max_turn_rate = 0.5;  //!< rad/s
		double room_width = 7, room_height = 4;  //!< m (the paper's living room)
		PathType path_type = PathType::Random;
		/** Waypoints "x1 y1 x2 y2 ..." visited cyclically (path_type=waypoints). */
		std::vector<double> waypoints;
		/** Random goals keep this distance to the walls (m). */
		double wall_margin = 0.5;

		// Odometry errors
		double odo_sigma_T = 0.05;  //!< m/sqrt(m)
		double odo_sigma_R = 0.05;  //!< rad/sqrt(rad)
		double odo_sigma_R_per_meter = 0.02;  //!< rad/sqrt(m)
		double odo_scale_bias = 0.0;  //!< relative error of distances
		double odo_turn_bias = 0.0;  //!< relative error of rotations
		double slip_probability = 0.0;  //!< per odometry period
		double slip_std = 0.05;  //!< m, xy error of one slip

		// Camera / front-end
		LandmarkType landmark_type = LandmarkType::Visual;
		double camera_rate = 2.0;  //!< frames per second
		/** A visual landmark is a scene: points at a depth in
		 * [scene_depth_min, scene_depth_max] ahead of the camera when it was
		 * created. It is recognized when the scene centre is inside the central
		 * part of the field of view, seen from a direction within
		 * max_view_change of the original one, at a distance within a factor
		 * max_scale_change of the original. */
		double camera_fov = 60 * M_PI / 180;  //!< rad, full horizontal angle
		double scene_depth_min = 1.5, scene_depth_max = 3.0;  //!< m
		double max_view_change = 30 * M_PI / 180;  //!< rad
		double max_scale_change = 1.5;
		double recognition_probability = 0.8;
		double creation_min_distance = 0.8;  //!< m to every other landmark frame
		double creation_min_angle = 45 * M_PI / 180;  //!< or this heading change
		double meas_std_dx = 0.06, meas_std_dy = 0.06;  //!< m
		double meas_std_dphi = 2 * M_PI / 180;  //!< rad
		/** Per-landmark reconstruction error of its frame (fixed per landmark). */
		double landmark_frame_std_xy = 0.02;
		double landmark_frame_std_phi = 0.5 * M_PI / 180;
		/** Measurements with bad statistics and large errors (the pre-filter
		 * must reject them). */
		double bad_measurement_probability = 0.1;
		/** False recognitions that pass the pre-filter (wrong landmark ID). */
		double false_recognition_probability = 0.0;

		// Range-bearing landmarks
		uint32_t point_landmarks = 20;
		double rb_max_range = 5.0;  //!< m
		double rb_fov = 70 * M_PI / 180;  //!< rad, full angle
		double rb_std_range = 0.05;  //!< m
		double rb_std_bearing = 1 * M_PI / 180;  //!< rad

		// Kidnapping: at each listed time the robot is carried to a random
		// free pose at least kidnap_min_distance away; odometry sees nothing.
		std::vector<double> kidnap_times;
		double kidnap_min_distance = 3.0;

		TOdometryErrorModel odometryErrors() const
		{
			return {odo_sigma_T, odo_sigma_R, odo_sigma_R_per_meter, odo_scale_bias, odo_turn_bias, slip_probability, slip_std};
		}

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& cfg,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& cfg,
			const std::string& section) const override;
	};

	explicit CMeasurementSimulator(const CMeasurementSimulator::TOptions& o) : m_options(o) {}
	SimulatedRun run() const;

	/** UNIX time of the first step. */
	static constexpr double kStartTime = 1700000000.0;

   private:
	CMeasurementSimulator::TOptions m_options;
};
/** Options from INI text with --set overrides applied: unknown keys in
 * [vslam_sim] and bad values are ConfigErrors naming the key. */
CMeasurementSimulator::TOptions loadMeasurementSimOptions(
	const std::string& iniText, const std::vector<config::Override>& overrides);
}  // namespace vslam

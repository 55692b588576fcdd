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
#include <libvslam/models/LandmarkTypes.h>
#include <libvslam/sim/TMeasurementSimOptions.h>
#include <mrpt/core/Clock.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CSensoryFrame.h>

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
	explicit CMeasurementSimulator(const TMeasurementSimOptions& o) : m_options(o) {}
	SimulatedRun run() const;

	/** UNIX time of the first step. */
	static constexpr double kStartTime = 1700000000.0;

   private:
	TMeasurementSimOptions m_options;
};
}  // namespace vslam

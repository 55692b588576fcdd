#pragma once
/** \file CSmoothedPose.h
 * A continuous pose for a robot's controller: the filter's posterior mean
 * jumps when a measurement corrects it, a controller must not. The
 * smoothed pose moves with the odometry and takes the filter's correction
 * in gradually: each step a share 1 - exp(-dt / time_constant) of what
 * separates it from the posterior mean, at most max_correction_speed m/s
 * of position (and that over a 1 m lever of heading). A declared kidnap
 * makes it jump: the robot is elsewhere, and a slow slide there would be
 * wrong for seconds.
 */
#include <libvslam/models/SE2.h>
#include <mrpt/config/CLoadableOptions.h>

#include <optional>

namespace vslam
{
class CSmoothedPose
{
   public:
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		static constexpr const char* kSection = "vslam_smoothed_pose";
		double time_constant = 2.0;  //!< s
		double max_correction_speed = 0.05;  //!< m/s (heading: rad/s over a 1 m lever)

		void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section) override;
		void saveToConfigFile(mrpt::config::CConfigFileBase& cfg, const std::string& section) const override;
	};

	explicit CSmoothedPose(const TOptions& options) : m_o(options) {}

	/** One step: the odometry increment since the last (robot frame), the
	 * time since it (s), the filter's mean, and whether the filter declared
	 * (or took back) a kidnap this step. Returns the smoothed pose. */
	const se2::Pose& update(const se2::Pose& odometryIncrement, double dt, const se2::Pose& mean, bool jump);

	/** The pose so far (nullopt before the first update). */
	const std::optional<se2::Pose>& pose() const { return m_pose; }

   private:
	TOptions m_o;
	std::optional<se2::Pose> m_pose;
};
}  // namespace vslam

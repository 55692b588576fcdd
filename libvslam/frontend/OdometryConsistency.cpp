#include <libvslam/frontend/OdometryConsistency.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace vslam
{
mrpt::poses::CPose2D predictFromEarlier(const ReportedRecognition& earlier, const mrpt::poses::CPose2D& odometryNow)
{
	// The landmark frame in the odometry frame, seen from the robot now.
	return (mrpt::poses::CPose2D(earlier.odometryPose) + mrpt::poses::CPose2D(earlier.landmarkInRobot)) -
		odometryNow;
}

bool agreesWithOdometry(const std::optional<ReportedRecognition>& earlier, double time,
	const mrpt::poses::CPose2D& odometryNow, const mrpt::poses::CPose2D& landmarkInRobot,
	const TOdometryConsistencyOptions& tolerance)
{
	if (tolerance.horizon <= 0 || !earlier) return true;
	const double age = time - earlier->time;
	if (age < 0 || age > tolerance.horizon) return true;
	const mrpt::poses::CPose2D predicted = predictFromEarlier(*earlier, odometryNow);
	const double positionError = std::hypot(predicted.x() - landmarkInRobot.x(), predicted.y() - landmarkInRobot.y());
	const double headingError = std::abs(mrpt::math::wrapToPi(predicted.phi() - landmarkInRobot.phi()));
	return positionError <= tolerance.position + tolerance.relative * landmarkInRobot.norm() &&
		headingError <= tolerance.heading;
}
}  // namespace vslam

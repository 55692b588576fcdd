#include <libvslam/eval/LandmarkScaleOracle.h>

using namespace vslam;

se2::Pose vslam::cameraInLandmark(const se2::Pose& z, const se2::Pose& mount)
{
	return se2::compose(se2::inverse(z), mount);
}

se2::Pose vslam::withoutScale(const se2::Pose& z, const se2::Pose& mount, double k)
{
	const se2::Pose camera = cameraInLandmark(z, mount);
	const se2::Pose rescaled{camera.x / k, camera.y / k, camera.phi};
	return se2::inverse(se2::compose(rescaled, se2::inverse(mount)));
}

double vslam::fitLandmarkScale(
	const std::vector<std::pair<se2::Pose, se2::Pose>>& measuredAndTrue, const se2::Pose& mount)
{
	double cross = 0, trueSquared = 0;
	for (const auto& [measured, truth] : measuredAndTrue)
	{
		const se2::Pose m = cameraInLandmark(measured, mount), t = cameraInLandmark(truth, mount);
		cross += m.x * t.x + m.y * t.y;
		trueSquared += t.x * t.x + t.y * t.y;
	}
	return trueSquared > 0 ? cross / trueSquared : 1.0;
}

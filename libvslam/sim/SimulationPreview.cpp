#include <libvslam/core/InputError.h>
#include <libvslam/sim/CVisualSimulator.h>
#include <libvslam/world/FreeSpace.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace vslam
{
void writeSimulationPreview(
	const world::FloorPlan& plan, const VisualSimRun& run, const std::string& pngFile)
{
	constexpr double ppm = 60;  // pixels per metre
	const auto [lo, hi] = plan.bounds();
	const Eigen::Vector2d origin = lo - Eigen::Vector2d(0.3, 0.3);
	const int W = static_cast<int>((hi[0] - lo[0] + 0.6) * ppm), H = static_cast<int>((hi[1] - lo[1] + 0.6) * ppm);
	cv::Mat img(H, W, CV_8UC3, cv::Scalar(255, 255, 255));
	const auto px = [&](double x, double y) {
		return cv::Point(static_cast<int>((x - origin[0]) * ppm), static_cast<int>(H - 1 - (y - origin[1]) * ppm));
	};
	for (const auto& poly : plan.solidPolygons())
	{
		std::vector<cv::Point> pts;
		for (const auto& c : poly) pts.push_back(px(c[0], c[1]));
		cv::fillConvexPoly(img, pts, cv::Scalar(90, 90, 90), cv::LINE_AA);
	}
	for (const auto& d : plan.doors) cv::line(img, px(d.a[0], d.a[1]), px(d.b[0], d.b[1]), cv::Scalar(40, 90, 160), 3);
	for (const auto& q : plan.pictures)
		cv::line(img, px(q.a[0], q.a[1]), px(q.b[0], q.b[1]), cv::Scalar(200, 120, 200), 3);
	const auto drawPath = [&](const Trajectory& path, const cv::Scalar& colour) {
		for (size_t i = 1; i < path.size(); i++)
		{
			if (std::find(run.kidnapSteps.begin(), run.kidnapSteps.end(), i + 1) != run.kidnapSteps.end() &&
				&path == &run.truePath)
			{
				cv::line(img, px(path[i - 1].pose.x, path[i - 1].pose.y), px(path[i].pose.x, path[i].pose.y),
					cv::Scalar(255, 120, 0), 1, cv::LINE_AA);
				continue;
			}
			cv::line(img, px(path[i - 1].pose.x, path[i - 1].pose.y), px(path[i].pose.x, path[i].pose.y), colour,
				1, cv::LINE_AA);
		}
	};
	drawPath(run.odometryPath, cv::Scalar(0, 0, 220));
	drawPath(run.truePath, cv::Scalar(0, 160, 0));
	if (!run.truePath.empty())
		cv::circle(img, px(run.truePath[0].pose.x, run.truePath[0].pose.y), 5, cv::Scalar(0, 0, 0), 2);
	cv::putText(img, "true path (green), odometry (red), kidnap (blue), 1 m grid", cv::Point(5, 15),
		cv::FONT_HERSHEY_SIMPLEX, 0.4, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
	for (double x = std::ceil(origin[0]); x < hi[0] + 0.3; x += 1)
		cv::line(img, px(x, origin[1]), px(x, origin[1] + 0.1), cv::Scalar(0, 0, 0));
	for (double y = std::ceil(origin[1]); y < hi[1] + 0.3; y += 1)
		cv::line(img, px(origin[0], y), px(origin[0] + 0.1, y), cv::Scalar(0, 0, 0));
	if (!cv::imwrite(pngFile, img)) throw InputError("cannot write preview '" + pngFile + "'");
}
}  // namespace vslam

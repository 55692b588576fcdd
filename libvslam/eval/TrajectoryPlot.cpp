#include <libvslam/core/InputError.h>
#include <libvslam/eval/TrajectoryPlot.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <limits>

namespace vslam
{
void writeTrajectoryPlot(const world::FloorPlan* plan, const std::vector<PlotSeries>& series, const std::string& pngFile,
	const std::vector<se2::Pose>& landmarks)
{
	constexpr double inf = std::numeric_limits<double>::infinity();
	Eigen::Vector2d lo(inf, inf), hi(-inf, -inf);
	if (plan) std::tie(lo, hi) = plan->bounds();
	for (const auto& s : series)
		for (const auto& p : *s.path)
			lo = lo.cwiseMin(Eigen::Vector2d(p.pose.x, p.pose.y)), hi = hi.cwiseMax(Eigen::Vector2d(p.pose.x, p.pose.y));
	if (!(lo[0] <= hi[0])) lo.setZero(), hi.setOnes();
	const double span = std::max({hi[0] - lo[0], hi[1] - lo[1], 1.0});
	const double ppm = std::clamp(900 / span, 20.0, 120.0);  // pixels per metre
	const Eigen::Vector2d origin = lo - Eigen::Vector2d(0.3, 0.3);
	const int W = static_cast<int>((hi[0] - lo[0] + 0.6) * ppm);
	const int legend = 18 * static_cast<int>(series.size() + 2);
	const int H = static_cast<int>((hi[1] - lo[1] + 0.6) * ppm) + legend;
	cv::Mat img(H, std::max(W, 320), CV_8UC3, cv::Scalar(255, 255, 255));
	const auto px = [&](double x, double y) {
		return cv::Point(static_cast<int>((x - origin[0]) * ppm), static_cast<int>(H - 1 - (y - origin[1]) * ppm));
	};
	if (plan)
	{
		for (const auto& poly : plan->solidPolygons())
		{
			std::vector<cv::Point> pts;
			for (const auto& c : poly) pts.push_back(px(c[0], c[1]));
			cv::fillConvexPoly(img, pts, cv::Scalar(110, 110, 110), cv::LINE_AA);
		}
		const cv::Scalar doorColour(60, 110, 170);
		for (const auto& d : plan->doors) cv::line(img, px(d.a[0], d.a[1]), px(d.b[0], d.b[1]), doorColour, 3);
		for (const auto& o : plan->openings)
			if (o.kind == world::Opening::Kind::Doorway && o.hasLeaf)
			{
				const auto [hinge, end] = world::doorLeaf(*plan, o);
				cv::line(img, px(hinge[0], hinge[1]), px(end[0], end[1]), doorColour, 2);
			}
		for (const auto& q : plan->pictures)  // on the wall's face, not over its doorways
			if (q.framed) cv::line(img, px(q.a[0], q.a[1]), px(q.b[0], q.b[1]), cv::Scalar(200, 140, 200), 1);
	}
	const cv::Scalar landmarkColour(0, 140, 255);
	for (const auto& l : landmarks)
		cv::arrowedLine(img, px(l.x, l.y), px(l.x + 0.25 * std::cos(l.phi), l.y + 0.25 * std::sin(l.phi)),
			landmarkColour, 2, cv::LINE_AA, 0, 0.4);
	for (size_t k = 0; k < series.size(); k++)
	{
		const auto& s = series[k];
		const cv::Scalar colour(s.rgb[2], s.rgb[1], s.rgb[0]);
		const auto& path = *s.path;
		for (size_t i = 1; i < path.size(); i++)
		{
			const bool jump = std::find(s.jumps.begin(), s.jumps.end(), i) != s.jumps.end();
			cv::line(img, px(path[i - 1].pose.x, path[i - 1].pose.y), px(path[i].pose.x, path[i].pose.y),
				jump ? cv::Scalar(255, 150, 0) : colour, jump ? 1 : 2, cv::LINE_AA);
		}
		if (!path.empty()) cv::circle(img, px(path[0].pose.x, path[0].pose.y), 5, colour, 2, cv::LINE_AA);
		const cv::Point at(8, 16 + 18 * static_cast<int>(k));
		cv::line(img, at + cv::Point(0, -4), at + cv::Point(24, -4), colour, 3);
		cv::putText(img, s.label, at + cv::Point(32, 0), cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
	}
	const int rows = static_cast<int>(series.size()) + (landmarks.empty() ? 0 : 1);
	if (!landmarks.empty())
	{
		const cv::Point at(8, 16 + 18 * static_cast<int>(series.size()));
		cv::arrowedLine(img, at + cv::Point(0, -4), at + cv::Point(24, -4), landmarkColour, 2, cv::LINE_AA, 0, 0.4);
		cv::putText(img, "landmarks", at + cv::Point(32, 0), cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 1,
			cv::LINE_AA);
	}
	const cv::Point bar(8, 16 + 18 * rows);
	cv::line(img, bar + cv::Point(0, -4), bar + cv::Point(static_cast<int>(ppm), -4), cv::Scalar(0, 0, 0), 2);
	cv::putText(img, "1 m", bar + cv::Point(static_cast<int>(ppm) + 8, 0), cv::FONT_HERSHEY_SIMPLEX, 0.45,
		cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
	if (!cv::imwrite(pngFile, img)) throw InputError("cannot write plot '" + pngFile + "'");
}
}  // namespace vslam

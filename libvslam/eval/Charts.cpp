#include <libvslam/core/InputError.h>
#include <libvslam/eval/Charts.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace vslam
{
namespace
{
cv::Scalar bgr(const std::array<uint8_t, 3>& rgb) { return cv::Scalar(rgb[2], rgb[1], rgb[0]); }

void text(cv::Mat& img, const std::string& s, cv::Point at, double scale = 0.42)
{
	cv::putText(img, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
}

/** A round tick spacing giving about `count` ticks over `span`. */
double tickStep(double span, int count)
{
	const double raw = span / count;
	const double p = std::pow(10.0, std::floor(std::log10(raw)));
	for (const double m : {1.0, 2.0, 5.0})
		if (m * p >= raw) return m * p;
	return 10 * p;
}

std::string number(double v, double step)
{
	char buf[32];
	const int decimals = step >= 1 ? 0 : std::min(6, int(std::ceil(-std::log10(step))));
	std::snprintf(buf, sizeof buf, "%.*f", decimals, std::abs(v) < step * 1e-6 ? 0.0 : v);
	return buf;
}

/** The plotting area of a chart and its data ranges. */
class Canvas
{
   public:
	Canvas(const TChartOptions& o, double x0, double x1, double y0, double y1)
		: m_img(o.height, o.width, CV_8UC3, cv::Scalar(255, 255, 255)),
		  m_area(70, 44, o.width - 90, o.height - 44 - o.bottomMargin),
		  m_x0(x0), m_x1(x1 > x0 ? x1 : x0 + 1), m_y0(y0), m_y1(y1 > y0 ? y1 : y0 + 1)
	{
		text(m_img, o.title, cv::Point(m_area.x, 18), 0.5);
		text(m_img, o.xLabel, cv::Point(m_area.x + m_area.width / 2 - 40, o.height - 12));
		text(m_img, o.yLabel, cv::Point(4, m_area.y - 8));
		const double xs = tickStep(m_x1 - m_x0, 10), ys = tickStep(m_y1 - m_y0, 5);
		for (double v = std::ceil(m_x0 / xs) * xs; v <= m_x1 + 1e-9 * xs; v += xs)
		{
			cv::line(m_img, at(v, m_y0), at(v, m_y1), cv::Scalar(230, 230, 230), 1);
			text(m_img, number(v, xs), at(v, m_y0) + cv::Point(-10, 18));
		}
		for (double v = std::ceil(m_y0 / ys) * ys; v <= m_y1 + 1e-9 * ys; v += ys)
		{
			cv::line(m_img, at(m_x0, v), at(m_x1, v), cv::Scalar(230, 230, 230), 1);
			text(m_img, number(v, ys), at(m_x0, v) + cv::Point(-60, 5));
		}
		cv::rectangle(m_img, m_area, cv::Scalar(0, 0, 0), 1);
		for (const auto& m : o.markers)
			for (const double x : m.x) cv::line(m_img, at(x, m_y0), at(x, m_y1), bgr(m.rgb), 1, cv::LINE_AA);
	}

	cv::Point at(double x, double y) const
	{
		const double u = (x - m_x0) / (m_x1 - m_x0), v = (y - m_y0) / (m_y1 - m_y0);
		return cv::Point(m_area.x + int(std::lround(u * m_area.width)),
			m_area.y + m_area.height - int(std::lround(std::clamp(v, -0.02, 1.02) * m_area.height)));
	}

	/** Legend entries, left to right under the title. */
	void legend(const std::string& label, const cv::Scalar& colour)
	{
		if (label.empty()) return;
		const cv::Point p(m_area.x + 10 + m_legendX, m_area.y + 16);
		cv::line(m_img, p + cv::Point(0, -4), p + cv::Point(22, -4), colour, 3);
		text(m_img, label, p + cv::Point(28, 0));
		m_legendX += 40 + 8 * int(label.size());
	}

	cv::Mat& image() { return m_img; }

	void write(const std::string& pngFile) const
	{
		if (!cv::imwrite(pngFile, m_img)) throw InputError("cannot write plot '" + pngFile + "'");
	}

   private:
	cv::Mat m_img;
	cv::Rect m_area;
	double m_x0, m_x1, m_y0, m_y1;
	int m_legendX = 0;
};
}  // namespace

void writeLineChart(const std::vector<ChartSeries>& series, const TChartOptions& o, const std::string& pngFile)
{
	constexpr double inf = std::numeric_limits<double>::infinity();
	double x0 = inf, x1 = -inf, y1 = 0;
	for (const auto& s : series)
		for (size_t i = 0; i < s.x.size() && i < s.y.size(); i++)
			if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
				x0 = std::min(x0, s.x[i]), x1 = std::max(x1, s.x[i]), y1 = std::max(y1, s.y[i]);
	if (!(x0 <= x1)) x0 = 0, x1 = 1;
	Canvas canvas(o, x0, x1, 0, y1 * 1.15);  // room for the legend
	for (const auto& s : series)
	{
		const cv::Scalar colour = bgr(s.rgb);
		for (size_t i = 1; i < s.x.size() && i < s.y.size(); i++)
			if (std::isfinite(s.y[i - 1]) && std::isfinite(s.y[i]))
				cv::line(canvas.image(), canvas.at(s.x[i - 1], s.y[i - 1]), canvas.at(s.x[i], s.y[i]), colour, 1,
					cv::LINE_AA);
		canvas.legend(s.label, colour);
	}
	for (const auto& m : o.markers)
		if (!m.x.empty()) canvas.legend(m.label, bgr(m.rgb));
	canvas.write(pngFile);
}

void writeBarChart(const std::vector<double>& values, const std::array<uint8_t, 3>& rgb, const TChartOptions& o,
	const std::string& pngFile, const std::vector<double>& spreads, const std::vector<std::string>& labels,
	const std::vector<std::array<uint8_t, 3>>& barColours)
{
	const auto spread = [&](size_t i) { return i < spreads.size() && std::isfinite(spreads[i]) ? spreads[i] : 0.0; };
	double top = 0;
	for (size_t i = 0; i < values.size(); i++)
		if (std::isfinite(values[i])) top = std::max(top, values[i] + spread(i));
	TChartOptions withRoom = o;
	if (!labels.empty())
	{
		const int rows = 14 * int(std::min<size_t>(labels.size(), 4));
		withRoom.height += rows;
		withRoom.bottomMargin += rows;
	}
	Canvas canvas(withRoom, 0.5, double(values.size()) + 0.5, 0, top * 1.1);
	for (size_t i = 0; i < values.size(); i++)
	{
		const double x = double(i + 1);
		if (std::isfinite(values[i]) && values[i] > 0)
			cv::rectangle(canvas.image(), canvas.at(x - 0.4, values[i]), canvas.at(x + 0.4, 0),
				bgr(i < barColours.size() ? barColours[i] : rgb), cv::FILLED);
		if (spread(i) > 0 && std::isfinite(values[i]))
		{
			const cv::Scalar black(0, 0, 0);
			cv::line(canvas.image(), canvas.at(x, values[i] - spread(i)), canvas.at(x, values[i] + spread(i)), black, 1);
			for (const double y : {values[i] - spread(i), values[i] + spread(i)})
				cv::line(canvas.image(), canvas.at(x - 0.1, y), canvas.at(x + 0.1, y), black, 1);
		}
		if (i < labels.size())
		{
			// Labels in rows under the axis, so neighbours do not overlap.
			const cv::Point under = canvas.at(x, 0) + cv::Point(-30, 34 + 14 * int(i % 4));
			text(canvas.image(), labels[i], under, 0.38);
		}
	}
	canvas.write(pngFile);
}
}  // namespace vslam

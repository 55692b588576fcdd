#pragma once
/** \file Charts.h
 * Plain PNG charts for the paper's figures of a run: lines over time (the
 * position error of vslam and of odometry, its Fig. 4; the particle
 * cloud's spread and the dual share, with kidnaps marked) and bars (the
 * measurements per landmark, its Fig. 5). Axes with round ticks, a legend,
 * optional vertical markers. */
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace vslam
{
struct ChartSeries
{
	std::vector<double> x, y;  //!< same length
	std::array<uint8_t, 3> rgb{0, 0, 0};
	std::string label;
};

struct ChartMarkers
{
	std::vector<double> x;  //!< vertical lines at these abscissae
	std::array<uint8_t, 3> rgb{230, 120, 0};
	std::string label;
};

struct TChartOptions
{
	std::string title, xLabel, yLabel;
	std::vector<ChartMarkers> markers;
	int width = 960, height = 360;
	int bottomMargin = 50;  //!< pixels under the plotting area (tick numbers, axis label)
};

/** Line chart; throws InputError if the file cannot be written. */
void writeLineChart(const std::vector<ChartSeries>& series, const TChartOptions& options, const std::string& pngFile);

/** Bar chart of \a values at x = 1, 2, ...; with \a spreads, an error bar
 * of +- spread on each; with \a labels, a label under each bar; with
 * \a barColours, each bar's own colour instead of \a rgb. Throws InputError if the file cannot be written. */
void writeBarChart(const std::vector<double>& values, const std::array<uint8_t, 3>& rgb, const TChartOptions& options,
	const std::string& pngFile, const std::vector<double>& spreads = {}, const std::vector<std::string>& labels = {},
	const std::vector<std::array<uint8_t, 3>>& barColours = {});
}  // namespace vslam

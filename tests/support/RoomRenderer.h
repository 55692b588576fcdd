#pragma once
/** \file RoomRenderer.h
 * Test fixture: camera images inside a rectangular room whose four walls
 * carry distinct random textures (multi-scale blurred noise), rendered by
 * casting each pixel's ray to the wall it hits (a convex room: exactly one
 * wall per ray). Exact geometry for front-end tests; the real rendered
 * worlds are the simulator's (issue 4).
 */
#include <mrpt/img/TCamera.h>
#include <mrpt/poses/CPose3D.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <array>
#include <cmath>
#include <random>

namespace vslam::testing
{
class RoomRenderer
{
   public:
	/** Room [0, width] x [0, depth], walls from z = 0 to height, texture
	 * resolution in pixels per metre. */
	RoomRenderer(double width, double depth, double height, uint32_t seed, int pixelsPerMetre = 150)
		: m_w(width), m_d(depth), m_h(height), m_ppm(pixelsPerMetre)
	{
		std::mt19937 rng(seed);
		const double lengths[4] = {width, depth, width, depth};
		for (int i = 0; i < 4; i++) m_tex[i] = texture(lengths[i], rng);
	}

	/** The image seen by a camera at `camera` (axes: z forward, x right, y down). */
	cv::Mat render(const mrpt::img::TCamera& cam, const mrpt::poses::CPose3D& camera) const
	{
		const int W = static_cast<int>(cam.ncols), H = static_cast<int>(cam.nrows);
		cv::Mat out(H, W, CV_8UC1, cv::Scalar(0));
		const auto R = camera.getRotationMatrix();
		const double ox = camera.x(), oy = camera.y(), oz = camera.z();
		for (int v = 0; v < H; v++)
			for (int u = 0; u < W; u++)
			{
				const double cx = (u - cam.cx()) / cam.fx(), cy = (v - cam.cy()) / cam.fy();
				const double dx = R(0, 0) * cx + R(0, 1) * cy + R(0, 2);
				const double dy = R(1, 0) * cx + R(1, 1) * cy + R(1, 2);
				const double dz = R(2, 0) * cx + R(2, 1) * cy + R(2, 2);
				// Walls: 0 y=0, 1 x=w, 2 y=d, 3 x=0.
				double best = 1e18;
				int wall = -1;
				double s = 0;
				const auto hit = [&](int i, double t, double along) {
					if (t > 1e-6 && t < best) best = t, wall = i, s = along;
				};
				if (dy < 0) hit(0, -oy / dy, ox + (-oy / dy) * dx);
				if (dx > 0) hit(1, (m_w - ox) / dx, oy + ((m_w - ox) / dx) * dy);
				if (dy > 0) hit(2, (m_d - oy) / dy, m_w - (ox + ((m_d - oy) / dy) * dx));
				if (dx < 0) hit(3, -ox / dx, m_d - (oy + (-ox / dx) * dy));
				if (wall < 0) continue;
				const double z = oz + best * dz;
				if (z < 0 || z > m_h) continue;  // floor and ceiling stay black
				const cv::Mat& tex = m_tex[wall];
				const int tu = std::clamp(static_cast<int>(s * m_ppm), 0, tex.cols - 1);
				const int tv = std::clamp(static_cast<int>((m_h - z) * m_ppm), 0, tex.rows - 1);
				out.at<uchar>(v, u) = tex.at<uchar>(tv, tu);
			}
		return out;
	}

   private:
	cv::Mat texture(double length, std::mt19937& rng) const
	{
		const int cols = static_cast<int>(length * m_ppm) + 1, rows = static_cast<int>(m_h * m_ppm) + 1;
		cv::Mat acc(rows, cols, CV_32F, cv::Scalar(0));
		std::uniform_real_distribution<float> u(0, 1);
		for (double sigma : {1.5, 4.0, 10.0})
		{
			cv::Mat noise(rows, cols, CV_32F);
			for (int r = 0; r < rows; r++)
				for (int c = 0; c < cols; c++) noise.at<float>(r, c) = u(rng);
			cv::GaussianBlur(noise, noise, {0, 0}, sigma);
			cv::normalize(noise, noise, 0, 1, cv::NORM_MINMAX);
			acc += noise;
		}
		cv::Mat out;
		cv::normalize(acc, acc, 0, 255, cv::NORM_MINMAX);
		acc.convertTo(out, CV_8U);
		return out;
	}

	double m_w, m_d, m_h;
	int m_ppm;
	std::array<cv::Mat, 4> m_tex;
};
}  // namespace vslam::testing

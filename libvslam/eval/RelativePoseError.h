#pragma once
/** \file RelativePoseError.h
 * RPE as in Sturm et al. 2012 (TUM RGB-D benchmark), planar: for every
 * associated pose i and the first pose j a window later (in time, or in
 * distance travelled along the ground truth), the error of the estimated
 * motion from i to j against the true one,
 *   E_ij = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j),
 * its translation (m) and rotation (rad). It measures drift per window and
 * needs no alignment. */
#include <libvslam/eval/ErrorSummary.h>
#include <libvslam/io/Trajectory.h>

namespace vslam
{
struct TRpeOptions
{
	enum class Window
	{
		Time,  //!< delta in seconds
		Distance  //!< delta in metres travelled along the ground truth
	};
	Window window = Window::Time;
	double delta = 1.0;
	/** Longest ground-truth gap to interpolate across (s); a time window may
	 * also end at most this much later than delta (gaps in the estimate). */
	double maxGap = 0.5;
};

struct RpeStats
{
	ErrorSummary translation;  //!< m, over the pose pairs
	ErrorSummary rotation;  //!< rad, absolute
	/** Mean true distance travelled over the windows (m): translation
	 * divided by it is the drift as a share of distance. */
	double meanTravelled = 0;
};

/** Throws InputError if a time window is asked for an estimate without
 * timestamps, or delta is not positive. */
RpeStats computeRpe(const Trajectory& estimate, const Trajectory& groundTruth, const TRpeOptions& options = {});
}  // namespace vslam

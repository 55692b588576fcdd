#include <libvslam/io/OdometryDelay.h>
#include <libvslam/models/SE2.h>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace vslam;

namespace
{
/** Heading and distance travelled since the first row, as functions of
 * time: piecewise linear, each row's (v, omega) held until the next. */
class CumulativeMotion
{
   public:
	explicit CumulativeMotion(const std::vector<std::vector<double>>& rows) : m_rows(rows)
	{
		m_heading.assign(rows.size(), 0);
		m_distance.assign(rows.size(), 0);
		for (size_t k = 1; k < rows.size(); k++)
		{
			const double dt = rows[k][0] - rows[k - 1][0];
			m_heading[k] = m_heading[k - 1] + rows[k - 1][2] * dt;
			m_distance[k] = m_distance[k - 1] + std::abs(rows[k - 1][1]) * dt;
		}
	}
	bool covers(double t) const { return t >= m_rows.front()[0] && t <= m_rows.back()[0]; }
	/** (heading, distance) at time t, which covers() */
	std::pair<double, double> at(double t) const
	{
		const auto it = std::upper_bound(
			m_rows.begin(), m_rows.end(), t, [](double v, const std::vector<double>& r) { return v < r[0]; });
		const size_t k = static_cast<size_t>(std::max<std::ptrdiff_t>(0, (it - m_rows.begin()) - 1));
		const double dt = t - m_rows[k][0];
		return {m_heading[k] + m_rows[k][2] * dt, m_distance[k] + std::abs(m_rows[k][1]) * dt};
	}

   private:
	const std::vector<std::vector<double>>& m_rows;
	std::vector<double> m_heading, m_distance;
};

struct SightingPair
{
	double t1, t2, bearingChange, parallaxFactor;  //!< parallaxFactor: sin(b) / r at the midpoint
};

std::vector<SightingPair> pairsOf(std::vector<BearingSighting> sightings, const TOdometryDelayOptions& o)
{
	std::sort(sightings.begin(), sightings.end(), [](const BearingSighting& a, const BearingSighting& b) {
		return a.landmark != b.landmark ? a.landmark < b.landmark : a.t < b.t;
	});
	std::vector<SightingPair> pairs;
	for (size_t i = 1; i < sightings.size(); i++)
	{
		const BearingSighting &a = sightings[i - 1], &b = sightings[i];
		if (a.landmark != b.landmark || !(b.t > a.t) || b.t - a.t > o.maxPairInterval) continue;
		if (a.range < o.minRange || b.range < o.minRange) continue;
		const double meanBearing = a.bearing + se2::wrap(b.bearing - a.bearing) / 2;
		pairs.push_back({a.t, b.t, se2::wrap(b.bearing - a.bearing), std::sin(meanBearing) * 2 / (a.range + b.range)});
	}
	return pairs;
}

double truncatedCost(const CumulativeMotion& motion, const std::vector<SightingPair>& pairs, double delay,
	double truncation, size_t& used)
{
	double cost = 0;
	used = 0;
	for (const auto& p : pairs)
	{
		// The motion at time t is the odometry's at t - delay.
		const double s1 = p.t1 - delay, s2 = p.t2 - delay;
		if (!motion.covers(s1) || !motion.covers(s2)) continue;
		const auto [h1, d1] = motion.at(s1);
		const auto [h2, d2] = motion.at(s2);
		const double predicted = -(h2 - h1) + (d2 - d1) * p.parallaxFactor;
		const double r = se2::wrap(p.bearingChange - predicted);
		cost += std::min(r * r, truncation * truncation);
		used++;
	}
	return cost;
}
}  // namespace

std::optional<double> vslam::estimateOdometryDelay(const std::vector<std::vector<double>>& odometryRows,
	std::vector<BearingSighting> sightings, const TOdometryDelayOptions& o)
{
	if (odometryRows.size() < 2) return std::nullopt;
	const CumulativeMotion motion(odometryRows);
	const std::vector<SightingPair> pairs = pairsOf(std::move(sightings), o);
	std::optional<double> best;
	double bestCost = std::numeric_limits<double>::infinity();
	const int steps = static_cast<int>(std::floor((o.maxDelay - o.minDelay) / o.step + 1e-9));
	for (int i = 0; i <= steps; i++)
	{
		const double delay = o.minDelay + i * o.step;
		size_t used = 0;
		const double cost = truncatedCost(motion, pairs, delay, o.truncation, used);
		if (used < o.minPairs) continue;
		// Per pair used, so delays that push pairs out of the span do not win by it.
		const double mean = cost / static_cast<double>(used);
		if (mean < bestCost) bestCost = mean, best = delay;
	}
	return best;
}

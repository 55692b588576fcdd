#pragma once
/** \file SeededRandom.h
 * The home generator's random numbers: a 64-bit Mersenne Twister and
 * uniform draws computed here (the standard distributions may differ
 * between library versions; a seed must give the same home everywhere).
 */
#include <cstdint>
#include <random>
#include <vector>

namespace vslam::world
{
class SeededRandom
{
   public:
	explicit SeededRandom(uint64_t seed) : m_engine(seed) {}

	/** Uniform in [lo, hi). */
	double uniform(double lo = 0, double hi = 1)
	{
		const double u = static_cast<double>(m_engine() >> 11) * (1.0 / 9007199254740992.0);
		return lo + (hi - lo) * u;
	}
	/** Uniform integer in [lo, hi]. */
	int integer(int lo, int hi) { return lo + static_cast<int>(m_engine() % static_cast<uint64_t>(hi - lo + 1)); }
	bool chance(double p) { return uniform() < p; }
	template <typename T>
	const T& pick(const std::vector<T>& v)
	{
		return v[static_cast<size_t>(m_engine() % v.size())];
	}

   private:
	std::mt19937_64 m_engine;
};
}  // namespace vslam::world

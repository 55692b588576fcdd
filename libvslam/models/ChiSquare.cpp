#include <libvslam/models/ChiSquare.h>

#include <cmath>
#include <stdexcept>

namespace vslam
{
double chiSquareCdf(double x, int dof)
{
	if (x <= 0) return 0;
	switch (dof)
	{
		case 1:
			return std::erf(std::sqrt(x / 2));
		case 2:
			return -std::expm1(-x / 2);
		case 3:
			return std::erf(std::sqrt(x / 2)) -
				std::sqrt(2 * x / M_PI) * std::exp(-x / 2);
		default:
			throw std::invalid_argument("chiSquareCdf: dof must be 1..3");
	}
}

double chiSquareQuantile(double p, int dof)
{
	if (!(p > 0 && p < 1))
		throw std::invalid_argument("chiSquareQuantile: p must be in (0,1)");
	double lo = 0, hi = 1;
	while (chiSquareCdf(hi, dof) < p) hi *= 2;
	for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; i++)
	{
		const double mid = 0.5 * (lo + hi);
		(chiSquareCdf(mid, dof) < p ? lo : hi) = mid;
	}
	return 0.5 * (lo + hi);
}
}  // namespace vslam

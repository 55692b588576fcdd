#include <libvslam/models/ChiSquare.h>

#include <boost/math/distributions/chi_squared.hpp>
#include <stdexcept>

namespace vslam
{
namespace
{
boost::math::chi_squared distribution(int dof)
{
	if (dof < 1) throw std::invalid_argument("chi-square: dof must be at least 1");
	return boost::math::chi_squared(dof);
}
}  // namespace

double chiSquareCdf(double x, int dof)
{
	const auto d = distribution(dof);
	return x <= 0 ? 0 : boost::math::cdf(d, x);
}

double chiSquareQuantile(double p, int dof)
{
	const auto d = distribution(dof);
	if (!(p > 0 && p < 1)) throw std::invalid_argument("chiSquareQuantile: p must be in (0,1)");
	return boost::math::quantile(d, p);
}
}  // namespace vslam

#pragma once
#include <stdexcept>
#include <string>

namespace vslam
{
/** The filter's state stopped being finite (NaN or infinite weights, poses
 * or covariances). The message names the step and the likely settings; the
 * apps exit with "other error" (4). */
class NumericalError : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};
}  // namespace vslam

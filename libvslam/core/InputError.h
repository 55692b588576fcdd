#pragma once
#include <stdexcept>
#include <string>

namespace vslam
{
/** Bad input data (corrupt or truncated rawlog, NaN odometry or
 * measurement, missing file). The message names the file or entry. */
class InputError : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};
}  // namespace vslam

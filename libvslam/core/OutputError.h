#pragma once
#include <stdexcept>
#include <string>

namespace vslam
{
/** An output could not be written (full disk, unwritable folder, I/O
 * error). The message names the file and the system's reason. Not the
 * input's fault: the apps exit with "other error" (4), not "bad input". */
class OutputError : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};
}  // namespace vslam

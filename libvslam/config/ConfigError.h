#pragma once
#include <stdexcept>
#include <string>

namespace vslam
{
/** A configuration problem (unknown key, unparsable or out-of-range value).
 * The message names the section and key; the app adds the file name. */
class ConfigError : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};
}  // namespace vslam

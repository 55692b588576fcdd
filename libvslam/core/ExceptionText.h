#pragma once
/** \file ExceptionText.h
 * MRPT exceptions carry banners, source locations and call stacks; users
 * need the messages. */
#include <exception>
#include <string>

namespace vslam
{
/** The message lines of an exception (nested MRPT messages joined by
 * ": "), without banners, locations and call stacks. */
std::string exceptionText(const std::exception& e);
}  // namespace vslam

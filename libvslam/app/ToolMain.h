#pragma once
/** \file ToolMain.h
 * The common frame of vslam's command-line tools: run the body, turn every
 * exception into one message "<tool>: error: ..." on stderr and the exit
 * codes the vslam app uses: 1 usage (the usage is printed too), 2
 * configuration, 3 bad input data, 4 anything else. */
#include <functional>
#include <string>

namespace vslam
{
int runTool(const std::string& tool, const std::string& usage, const std::function<int()>& body);
}  // namespace vslam

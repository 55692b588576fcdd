#pragma once
/** \file ConfigReference.h
 * The configuration reference (doc/configuration.md) from the options
 * themselves: every component writes its keys with their defaults and a
 * one-line meaning (saveToConfigFile), and this turns that INI text into
 * Markdown, one table per section. The meaning of a key is thus written
 * once, in the code, and the reference cannot drift from it. */
#include <libvslam/config/StrictRead.h>

#include <string>
#include <vector>

namespace vslam::config
{
/** Markdown of INI text written by saveToConfigFile ("key = value //
 * meaning" lines under "[section]" headers): a "### [section]" heading and
 * a table of key, default, allowed values and meaning per section, in the
 * text's order. The allowed range of a numeric key is the one its reader
 * checks (`numbers`, as a NumericKeyRecorder saw them). */
std::string markdownReference(const std::string& iniText, const std::vector<NumericKey>& numbers = {});
}  // namespace vslam::config

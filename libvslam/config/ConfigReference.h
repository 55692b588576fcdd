#pragma once
/** \file ConfigReference.h
 * The configuration reference (doc/configuration.md) from the options
 * themselves: every component writes its keys with their defaults and a
 * one-line meaning (saveToConfigFile), and this turns that INI text into
 * Markdown, one table per section. The meaning of a key is thus written
 * once, in the code, and the reference cannot drift from it. */
#include <string>

namespace vslam::config
{
/** Markdown of INI text written by saveToConfigFile ("key = value //
 * meaning" lines under "[section]" headers): a "### [section]" heading and
 * a table of key, default and meaning per section, in the text's order. */
std::string markdownReference(const std::string& iniText);
}  // namespace vslam::config

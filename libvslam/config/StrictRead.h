#pragma once
/** \file StrictRead.h
 * Strict INI readers. MRPT's read_double("abc") silently returns 0; these
 * parse the whole value, check its range and throw ConfigError naming the
 * section and key. A key that is absent keeps the given default.
 */
#include <libvslam/config/ConfigError.h>
#include <mrpt/config/CConfigFileBase.h>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace vslam::config
{
/** An allowed interval for a numeric value. */
struct Range
{
	double lo = -std::numeric_limits<double>::infinity();
	double hi = std::numeric_limits<double>::infinity();
	bool loInclusive = true;
	bool hiInclusive = true;

	static Range any() { return {}; }
	static Range positive() { return {0.0, Range{}.hi, false, true}; }
	static Range nonNegative() { return {0.0, Range{}.hi, true, true}; }
	static Range closed(double a, double b) { return {a, b, true, true}; }
	/** [a, b) */
	static Range halfOpen(double a, double b) { return {a, b, true, false}; }
	bool contains(double v) const;
	std::string describe() const;
};

/** A numeric key as the code reads it: its allowed range and its default. */
struct NumericKey
{
	std::string section, key;
	Range range;
	bool integer = false;
	double defaultValue = 0;
};

/** While one is alive, every numeric key read on this thread (present or
 * not) is recorded with its range: the options' own description of their
 * numbers, for the configuration reference and the extreme-value tests. */
class NumericKeyRecorder
{
   public:
	NumericKeyRecorder();
	~NumericKeyRecorder();
	NumericKeyRecorder(const NumericKeyRecorder&) = delete;
	NumericKeyRecorder& operator=(const NumericKeyRecorder&) = delete;
	const std::vector<NumericKey>& keys() const { return m_keys; }
	/** Called by the readers. */
	static void record(const NumericKey& key);

   private:
	std::vector<NumericKey> m_keys;
	NumericKeyRecorder* m_outer;
};

double readDouble(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, double defaultValue,
	const Range& range = Range::any());

/** Reads a value given in degrees and returns it in radians. */
double readDegreesAsRadians(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, double defaultRadians,
	const Range& rangeDegrees = Range::any());

int64_t readInt(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, int64_t defaultValue,
	const Range& range = Range::any());

/** readInt() for an int-sized count within [lo, hi]. */
int readCount(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, int defaultValue, double lo, double hi);

bool readBool(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, bool defaultValue);

std::string readString(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, const std::string& defaultValue);

/** Reads one of the given names (case-sensitive) and returns its index. An
 * integer index is accepted too. */
size_t readChoice(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, size_t defaultIndex,
	const std::vector<std::string>& names);

/** Reads one of the given names and returns it (readChoice's rules);
 * `defaultValue` must be one of them. */
std::string readWord(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, const std::string& defaultValue,
	const std::vector<std::string>& names);

/** The raw, trimmed value of a key ("" if absent). */
std::string rawValue(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key);

}  // namespace vslam::config

namespace vslam::config
{
/** A whitespace-separated list of finite numbers ("1 2.5 -3"); the default
 * if the key is absent. */
std::vector<double> readNumberList(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::string& key, const std::vector<double>& defaultValue);

/** The inverse of readNumberList, for saveToConfigFile. */
std::string joinNumbers(const std::vector<double>& values);
}  // namespace vslam::config

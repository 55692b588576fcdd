#pragma once
/** \file NumericTable.h
 * Whitespace-separated numeric text files (datasets, trajectories): rows of
 * finite numbers, comment lines starting with one of `commentChars`. */
#include <string>
#include <vector>

namespace vslam
{
/** Reads all rows; throws InputError naming the file and line on a
 * non-number, a non-finite value, or (if columns > 0) a row with another
 * number of columns. Rows of one file must all have the same width. A
 * last line without a newline that is not a whole row is skipped: it is
 * what a process killed while appending leaves (a write that crosses a
 * page of the file can be cut by SIGKILL). */
std::vector<std::vector<double>> readNumericTable(
	const std::string& file, const std::string& commentChars = "#%",
	size_t columns = 0);
}  // namespace vslam

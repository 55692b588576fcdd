#include <libvslam/core/InputError.h>
#include <libvslam/io/NumericTable.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace vslam
{
std::vector<std::vector<double>> readNumericTable(
	const std::string& file, const std::string& commentChars, size_t columns)
{
	std::ifstream in(file);
	if (!in) throw InputError("cannot open '" + file + "'");
	std::vector<std::vector<double>> rows;
	std::string line;
	size_t lineNo = 0;
	const auto where = [&] { return "'" + file + "', line " + std::to_string(lineNo) + ": "; };
	while (std::getline(in, line))
	{
		lineNo++;
		// A last line without its newline was cut by an interrupted write
		// (a process killed while appending): if it is not a whole row, it
		// is not data.
		const bool unterminated = in.eof();
		const auto b = line.find_first_not_of(" \t\r");
		if (b == std::string::npos || commentChars.find(line[b]) != std::string::npos)
			continue;
		std::istringstream ls(line);
		std::vector<double> row;
		std::string tok;
		bool numbers = true;
		while (ls >> tok)
		{
			char* end = nullptr;
			const double v = std::strtod(tok.c_str(), &end);
			if (*end != '\0' || !std::isfinite(v))
			{
				if (unterminated)
				{
					numbers = false;
					break;
				}
				throw InputError(where() + "'" + tok + "' is not a finite number");
			}
			row.push_back(v);
		}
		const size_t expected = columns ? columns : (rows.empty() ? row.size() : rows[0].size());
		if (unterminated && (!numbers || row.size() != expected)) break;
		if (row.size() != expected)
			throw InputError(where() + std::to_string(row.size()) + " columns, expected " +
				std::to_string(expected));
		rows.push_back(std::move(row));
	}
	return rows;
}
}  // namespace vslam

#pragma once
// The rows a benchmark's `run` printed (tab-separated, one header line per run), read back by its
// `summarize`.

#include <algorithm>
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "c2f/support/input_file.hpp"
#include "c2f/support/number_text.hpp"
#include "c2f/support/text_input.hpp"

namespace c2f::bench {

/// The rows of `path` with their fields: empty lines and header lines (beginning with
/// `header_start`, e.g. "scene\t") are skipped. Throws std::runtime_error naming the file when it
/// cannot be read (c2f/support/input_file.hpp: a regular file of at most 64 MiB) or a row has other
/// than `columns` fields, and std::invalid_argument when it
/// holds no row (a summary of nothing is no summary).
inline std::vector<std::vector<std::string>> read_summary_rows(const std::string& path,
                                                               const std::string& header_start,
                                                               std::size_t columns) {
  std::string text;
  try {
    text = read_input_file(path, "rows file", kMaxTextInputBytes);
  } catch (const std::invalid_argument& error) {
    throw std::runtime_error(error.what());
  }
  std::istringstream in(text);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line.rfind(header_start, 0) == 0) continue;
    std::vector<std::string> fields;
    std::stringstream stream(line);
    for (std::string field; std::getline(stream, field, '\t');) fields.push_back(field);
    if (fields.size() != columns)
      throw std::runtime_error("malformed row in '" + path + "': " + line);
    rows.push_back(std::move(fields));
  }
  if (rows.empty()) {
    throw std::invalid_argument("'" + path +
                                "' holds no rows to summarize (expected the rows a run printed)");
  }
  return rows;
}

/// Checks the numbers of the rows `rows` of the rows file `path`: every column in `numeric` must
/// hold a finite decimal number, or "nan" where the column is in `may_be_nan` too (a value a
/// run did not have, such as the time of reaching an energy it never reached). Throws
/// std::invalid_argument naming the file, the row (its first field) and the column
/// (`names[column]`): a NaN energy or a garbled number is no row to summarise.
inline void require_row_numbers(const std::vector<std::vector<std::string>>& rows,
                                const std::string& path, const char* const* names,
                                const std::vector<std::size_t>& numeric,
                                const std::vector<std::size_t>& may_be_nan) {
  for (const auto& row : rows) {
    for (const std::size_t column : numeric) {
      const std::string& text = row.at(column);
      const bool nan_text = text == "nan" || text == "-nan";
      const bool nan_allowed =
          std::find(may_be_nan.begin(), may_be_nan.end(), column) != may_be_nan.end();
      if ((nan_text && nan_allowed) || parse_real(text)) continue;
      throw std::invalid_argument("'" + path + "': row '" + printable(row.at(0)) + "', column " +
                                  names[column] + ": expected a finite number" +
                                  (nan_allowed ? " or nan" : "") + ", got '" + printable(text) +
                                  "'");
    }
  }
}

}  // namespace c2f::bench

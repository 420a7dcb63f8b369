// A table of numeric columns written as CSV, atomically (a `.part` file renamed when
// complete) and only when every value is finite. Private to src/.
#pragma once

#include <string>
#include <vector>

namespace tehl::internal {

struct CsvColumn {
  std::string header;          // column name with its unit, e.g. "h_min_m"
  std::vector<double> values;  // one per row
  bool integer = false;        // counts and flags: written without a fraction ("%.0f")
};

// Appends `value` to `text` as a CSV cell: "%.9e" (or "%.0f" when `integer`) in the C
// locale whatever the process's locale is (std::to_chars), so that a library user's decimal
// comma never ends up inside a comma-separated file.
void AppendCsvCell(std::string* text, double value, bool integer);

// Writes the columns (all of one length) with a header line, "%.9e" per value ("%.0f" in
// integer columns). Throws
// NonFiniteError (tehl/io/hdf5_writer.hpp) naming the column and row of a NaN or Inf, and
// std::filesystem::filesystem_error when the file cannot be written (io/atomic_file.hpp);
// nothing is left under `path` then.
void WriteCsvTable(const std::string& path, const std::vector<CsvColumn>& columns);

}  // namespace tehl::internal

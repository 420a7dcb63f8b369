#include "io/csv_table.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "tehl/io/hdf5_writer.hpp"

namespace tehl::internal {

void WriteCsvTable(const std::string& path, const std::vector<CsvColumn>& columns) {
  const size_t rows = columns.empty() ? 0 : columns.front().values.size();
  for (const auto& c : columns) {
    if (c.values.size() != rows)
      throw std::runtime_error("CSV " + path + ": column " + c.header + " has " +
                               std::to_string(c.values.size()) + " rows, expected " +
                               std::to_string(rows));
    CheckFinite("CSV column " + c.header, c.values);
  }
  std::string text;
  for (size_t j = 0; j < columns.size(); ++j) text += (j ? "," : "") + columns[j].header;
  text += "\n";
  char cell[40];
  for (size_t i = 0; i < rows; ++i) {
    for (size_t j = 0; j < columns.size(); ++j) {
      std::snprintf(cell, sizeof cell, columns[j].integer ? "%s%.0f" : "%s%.9e", j ? "," : "",
                    columns[j].values[i]);
      text += cell;
    }
    text += "\n";
  }
  WriteTextAtomically(path, text);
}

}  // namespace tehl::internal

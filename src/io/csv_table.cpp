#include "io/csv_table.hpp"

#include <charconv>
#include <filesystem>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "tehl/io/hdf5_writer.hpp"

namespace tehl::internal {

void AppendCsvCell(std::string* text, double value, bool integer) {
  char cell[40];
  const std::to_chars_result r =
      integer ? std::to_chars(cell, cell + sizeof cell, value, std::chars_format::fixed, 0)
              : std::to_chars(cell, cell + sizeof cell, value, std::chars_format::scientific, 9);
  text->append(cell, r.ptr);
}

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
  for (size_t i = 0; i < rows; ++i) {
    for (size_t j = 0; j < columns.size(); ++j) {
      if (j) text += ',';
      AppendCsvCell(&text, columns[j].values[i], columns[j].integer);
    }
    text += "\n";
  }
  WriteTextAtomically(path, text);
}

}  // namespace tehl::internal

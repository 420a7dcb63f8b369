#include "io/csv_table.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "tehl/io/hdf5_writer.hpp"

namespace tehl::internal {

void WriteCsvTable(const std::string& path, const std::vector<CsvColumn>& columns) {
  namespace fs = std::filesystem;
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
      std::snprintf(cell, sizeof cell, "%s%.9e", j ? "," : "", columns[j].values[i]);
      text += cell;
    }
    text += "\n";
  }
  const fs::path final_path(path);
  if (!final_path.parent_path().empty()) fs::create_directories(final_path.parent_path());
  const std::string tmp = path + ".part";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw std::runtime_error("cannot write " + tmp);
    }
  }
  fs::rename(tmp, final_path);
}

}  // namespace tehl::internal

// CSV text as rows of cells, for tests that read tehl's CSV output (index.csv, disc step
// tables). The files these tests read hold no quoted cells, so a comma always separates.
#pragma once

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace tehl::testing {

inline std::vector<std::vector<std::string>> CsvCells(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) continue;
    rows.emplace_back(1);
    for (char c : line) {
      if (c == ',')
        rows.back().emplace_back();
      else
        rows.back().back() += c;
    }
  }
  return rows;
}

inline std::vector<std::vector<std::string>> ReadCsvCells(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return CsvCells(text.str());
}

}  // namespace tehl::testing

// The study file as written: [study] keys and the [[vary]] parameters with their values,
// checked (every problem at its file:line). Expansion into scenes: study.cpp. Private to src/.
#pragma once

#include <string>
#include <vector>

#include "base/schema.hpp"
#include "tehl/scene/study.hpp"

namespace tehl::internal {

struct StudyFile {
  std::string base_case_path;   // resolved relative to the study file
  std::string mode;             // "grid" | "zip"
  std::string name;             // default: the study file's stem
  std::string output;           // default: results/<name>
  int base_line = 0, mode_line = 0;
  std::vector<StudyParameter> parameters;
};

// Throws InputError with every problem of the study file itself.
StudyFile ReadStudyFile(const std::string& path);

}  // namespace tehl::internal

// The [[vary]] entries of a study file (study_reader.cpp): one table checked at a time, its
// case key, label and values (a list, or a from/to/count range), every problem at its line.
// Private to study_reader.cpp and study_vary_reader.cpp.
#pragma once

#include <optional>
#include <string>
#include <toml.hpp>

#include "tehl/error.hpp"
#include "tehl/scene/study.hpp"

namespace tehl::internal {

// The most scenes of a study: a range's count, a grid's product of the list lengths.
inline constexpr int kMaxStudyScenes = 100000;

// A TOML value as a problem shows it: a literal, "[...]" or "{table}".
std::string ShowStudyValue(const toml::value& v);

// The line of a TOML value in its file (1-based).
int TomlLine(const toml::value& v);

// Reads the [[vary]] table `t`, entry `n` (1-based, for messages) of the study file `path`,
// starting at `table_line`. Nothing when it has problems; they go to `problems`.
std::optional<StudyParameter> ReadVaryTable(
    const std::string& path, const toml::value& t, int n, int table_line, ProblemList* problems);

}  // namespace tehl::internal

// Reading a case file: the schema check plus the cross-key rules (one of [gear] or
// [contact], exactly one speed and one load key, roughness only with its effect, the
// lubricant file exists). Private to src/: the typed structs are built from the Document by
// the scene layer.
#pragma once

#include <cstddef>
#include <string>

#include "base/gear_module.hpp"
#include "base/schema.hpp"

namespace tehl::internal {

// The longest [output] name accepted (file names are at most 255 bytes; the result files
// add suffixes such as "_profiles.png") [-].
inline constexpr size_t kMaxOutputNameChars = 200;

// Reads and checks a case file. Problems are collected in the returned Document; callers
// add their own and then call ThrowIfProblems().
Document ReadCaseDocument(const std::string& path);

// Resolves a lubricant name from a case ("sae40" or a path) relative to the case file:
// a path that exists (as given or beside the case, with or without .toml), else <name>.toml
// in $TEHL_LUBRICANT_DIR, in ../lubricants of the case, or in the data folders of
// io/data_dir.hpp (installed share/tehl/lubricants, source tree). "" when nothing matches.
std::string ResolveLubricantPath(const std::string& name, const std::string& case_path);

// What a lubricant name may be, with the folders searched (for "no such lubricant file").
std::string LubricantSearchText(const std::string& case_path);

}  // namespace tehl::internal

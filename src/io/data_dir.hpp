// Where tehl's data files are (lubricants/, scripts/): the folders to search, in order.
// An installed tehl finds share/tehl/<sub> beside its own library or program, wherever the
// prefix was moved to; a build tree finds the source tree's folder. Private to src/.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace tehl::internal {

// Existing folders for `sub` ("lubricants" or "scripts"), without repeats: first `env_var`
// (when set), then share/tehl/<sub> relative to the library file and to the running program
// (<dir>/../share/tehl/<sub>); only when neither exists (a build tree), the folder of the
// source tree named by tehl-source-dir.txt beside the library or program (written by CMake
// into the build tree, never installed), then the install prefix it was configured with.
std::vector<std::filesystem::path> DataDirs(const std::string& sub, const char* env_var);

}  // namespace tehl::internal

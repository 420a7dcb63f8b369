#include "io/data_dir.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>

namespace tehl::internal {
namespace fs = std::filesystem;
namespace {

// The file this function was loaded from: libtehl.so, or the program it is linked into.
fs::path LibraryFile() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&LibraryFile), &info) == 0 || !info.dli_fname) return {};
  std::error_code ec;
  const fs::path p = fs::canonical(info.dli_fname, ec);
  return ec ? fs::path() : p;
}

fs::path ProgramFile() {
  std::error_code ec;
  const fs::path p = fs::canonical("/proc/self/exe", ec);
  return ec ? fs::path() : p;
}

}  // namespace

std::vector<fs::path> DataDirs(const std::string& sub, const char* env_var) {
  std::vector<fs::path> candidates;
  if (const char* env = env_var ? std::getenv(env_var) : nullptr; env && *env)
    candidates.emplace_back(env);
  bool installed = false;  // an installed tehl uses its own data, not a build's source tree
  for (const fs::path& file : {LibraryFile(), ProgramFile()}) {
    if (file.empty()) continue;
    candidates.push_back(file.parent_path() / ".." / "share" / "tehl" / sub);
    std::error_code ec;
    installed = installed || fs::is_directory(candidates.back(), ec);
  }
  if (!installed) {
    // A build tree: its tehl-source-dir.txt (CMakeLists.txt) names the source tree.
    for (const fs::path& file : {LibraryFile(), ProgramFile()}) {
      if (file.empty()) continue;
      std::ifstream marker(file.parent_path() / "tehl-source-dir.txt");
      std::string source;
      if (marker && std::getline(marker, source) && !source.empty())
        candidates.push_back(fs::path(source) / sub);
    }
    if (sub == "lubricants") candidates.emplace_back(TEHL_INSTALL_LUBRICANT_DIR);
    if (sub == "scripts") candidates.emplace_back(TEHL_INSTALL_SCRIPT_DIR);
  }
  std::vector<fs::path> dirs;
  for (const fs::path& c : candidates) {
    std::error_code ec;
    if (!fs::is_directory(c, ec)) continue;
    const fs::path d = fs::canonical(c, ec);
    if (!ec && std::find(dirs.begin(), dirs.end(), d) == dirs.end()) dirs.push_back(d);
  }
  return dirs;
}

}  // namespace tehl::internal

#include "io/script_path.hpp"

#include <cstdlib>
#include <filesystem>
#include <vector>

namespace tehl::internal {

std::string FindScript(const std::string& name) {
  namespace fs = std::filesystem;
  std::vector<fs::path> dirs;
  if (const char* env = std::getenv("TEHL_SCRIPT_DIR")) dirs.emplace_back(env);
#ifdef TEHL_SOURCE_SCRIPT_DIR
  dirs.emplace_back(TEHL_SOURCE_SCRIPT_DIR);
#endif
#ifdef TEHL_INSTALL_SCRIPT_DIR
  dirs.emplace_back(TEHL_INSTALL_SCRIPT_DIR);
#endif
  for (const auto& d : dirs) {
    std::error_code ec;
    if (fs::is_regular_file(d / name, ec)) return (d / name).string();
  }
  return "";
}

}  // namespace tehl::internal

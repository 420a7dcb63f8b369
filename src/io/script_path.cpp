#include "io/script_path.hpp"

#include <filesystem>

#include "io/data_dir.hpp"

namespace tehl::internal {

std::string FindScript(const std::string& name) {
  namespace fs = std::filesystem;
  for (const fs::path& d : DataDirs("scripts", "TEHL_SCRIPT_DIR")) {
    std::error_code ec;
    if (fs::is_regular_file(d / name, ec)) return (d / name).string();
  }
  return "";
}

}  // namespace tehl::internal

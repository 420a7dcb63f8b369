#include "io/atomic_file.hpp"

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace tehl::internal {

void WriteTextAtomically(const std::string& path, const std::string& text) {
  namespace fs = std::filesystem;
  const fs::path final_path(path);
  if (!final_path.parent_path().empty()) fs::create_directories(final_path.parent_path());
  const std::string part = path + ".part";
  {
    errno = 0;  // so that a failure below reports its own cause
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) {
      const std::error_code why(errno != 0 ? errno : EIO, std::generic_category());
      std::error_code ignored;
      if (fs::is_regular_file(part, ignored)) fs::remove(part, ignored);
      throw fs::filesystem_error("cannot write", part, why);
    }
  }
  fs::rename(part, final_path);
}

}  // namespace tehl::internal

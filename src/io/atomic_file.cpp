#include "io/atomic_file.hpp"

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace tehl::internal {

void WriteTextAtomically(const std::string& path, const std::string& text) {
  namespace fs = std::filesystem;
  const fs::path final_path(path);
  std::error_code status_error;
  const fs::file_status status = fs::status(final_path, status_error);  // follows links
  if (!status_error && fs::exists(status) && !fs::is_regular_file(status) &&
      !fs::is_directory(status)) {
    // A device or a pipe (/dev/stdout, a FIFO): written in place, as there is no file to
    // replace (a rename would put a regular file where the device was).
    errno = 0;
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out)
      throw fs::filesystem_error(
          "cannot write", final_path,
          std::error_code(errno != 0 ? errno : EIO, std::generic_category()));
    return;
  }
  if (!final_path.parent_path().empty()) fs::create_directories(final_path.parent_path());
  const std::string part = path + ".part";
  // Only a file of our own goes: a folder in the way of the temporary file stays as it is.
  auto remove_part = [&] {
    std::error_code ignored;
    if (fs::is_regular_file(part, ignored)) fs::remove(part, ignored);
  };
  {
    errno = 0;  // so that a failure below reports its own cause
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();  // a disk that fills up may say so only when the file is closed
    if (!out) {
      const std::error_code why(errno != 0 ? errno : EIO, std::generic_category());
      remove_part();
      throw fs::filesystem_error("cannot write", part, why);
    }
  }
  std::error_code why;
  fs::rename(part, final_path, why);
  if (why) {  // e.g. a folder under the final name
    remove_part();
    throw fs::filesystem_error("cannot replace", final_path, why);
  }
}

}  // namespace tehl::internal

#include "ehl/fftw_wisdom.hpp"

#include <fftw3.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace tehl::internal {

std::string WisdomFile() {
  const char* v = std::getenv("TEHL_FFTW_WISDOM");
  return v ? v : "";
}

void ImportWisdomOnce() {
  static bool done = false;
  if (done) return;
  const std::string file = WisdomFile();
  if (file.empty()) return;
  done = true;
  ImportWisdom(file);
}

bool ImportWisdom(const std::string& path) {
  return fftw_import_wisdom_from_filename(path.c_str()) != 0;
}

bool ExportWisdom(const std::string& path) {
  const std::string tmp = path + ".tmp." + std::to_string(static_cast<long>(getpid()));
  if (fftw_export_wisdom_to_filename(tmp.c_str()) == 0) {
    std::remove(tmp.c_str());
    return false;
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    return false;
  }
  return true;
}

}  // namespace tehl::internal

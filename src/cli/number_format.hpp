// One number through a printf format ("%.4g", "%.2f"), for the reports of the commands.
// Private to the command line.
#pragma once

#include <cstdio>
#include <string>

namespace tehl::cli {

inline std::string Fmt(const char* format, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, x);
  return buf;
}

}  // namespace tehl::cli

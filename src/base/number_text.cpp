#include "base/number_text.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace tehl::internal {

std::string FormatReal(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  std::string s(buf, r.ptr);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string FormatShort(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 3);
  return std::string(buf, r.ptr);
}

bool ParseReal(std::string_view text, double* out, bool allow_non_finite) {
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && (text.front() == '-' || text.front() == '+')) return false;
  }
  if (text.empty()) return false;
  double v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size()) return false;
  if (!allow_non_finite && !std::isfinite(v)) return false;
  *out = v;
  return true;
}

double ParseRealOrThrow(std::string_view text, const std::string& what, bool allow_non_finite) {
  double v = 0;
  if (!ParseReal(text, &v, allow_non_finite))
    throw std::runtime_error(what + ": not a number: \"" + std::string(text) + "\"");
  return v;
}

}  // namespace tehl::internal

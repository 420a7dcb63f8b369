#include "base/toml_guard.hpp"

#include <cstdio>

namespace tehl::internal {
namespace {

// toml11 parses (and destroys) nested arrays and inline tables recursively, so a few thousand
// levels overflow the stack, and its time grows with the square of the parts of a dotted key
// ("a.a.a..." or "[a.a.a...]"): a 60 kB key takes minutes. No tehl file nests deeper than an
// array inside an inline table, and no key has more than three parts.
constexpr int kMaxNesting = 32;  // arrays and inline tables
constexpr int kMaxKeyDots = 32;  // dots in one key or table header
constexpr const char* kShallow =
    "tables of keys with numbers, strings, booleans and arrays of numbers";

// Length of the UTF-8 sequence starting at s[i], 0 if it is not one (RFC 3629, table 3-7 of
// the Unicode standard: the second byte's range depends on the first).
size_t Utf8Length(const std::string& s, size_t i) {
  const auto b = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned c = b(i);
  if (c < 0x80) return 1;
  size_t n = 0;
  unsigned lo = 0x80, hi = 0xBF;
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    if (c == 0xE0) lo = 0xA0;  // overlong
    if (c == 0xED) hi = 0x9F;  // surrogates
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    if (c == 0xF0) lo = 0x90;  // overlong
    if (c == 0xF4) hi = 0x8F;  // above U+10FFFF
  } else {
    return 0;  // continuation byte, C0/C1 (overlong) or F5..FF
  }
  if (i + n > s.size()) return 0;
  if (b(i + 1) < lo || b(i + 1) > hi) return 0;
  for (size_t k = 2; k < n; ++k)
    if (b(i + k) < 0x80 || b(i + k) > 0xBF) return 0;
  return n;
}

}  // namespace

TomlTextProblem FindInvalidUtf8(const std::string& s) {
  int line = 1;
  size_t line_start = 0;
  for (size_t i = 0; i < s.size();) {
    const size_t n = Utf8Length(s, i);
    if (n == 0) {
      char what[96];
      std::snprintf(what, sizeof what, "byte 0x%02x at column %zu is not UTF-8",
                    static_cast<unsigned char>(s[i]), i - line_start + 1);
      return {line, what, "UTF-8 text (a TOML file is UTF-8 throughout, comments included)"};
    }
    if (s[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
    i += n;
  }
  return {};
}

TomlTextProblem FindTooDeep(const std::string& s) {
  std::string open;    // the open brackets, '[' or '{'
  bool in_key = true;  // a key or a table header is being read
  bool line_start = true;
  int dots = 0, line = 1;
  for (size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '\n') {
      ++line;
      line_start = true;
      if (open.empty()) {
        in_key = true;
        dots = 0;
      }
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r') continue;
    const bool header = line_start && open.empty() && c == '[';
    line_start = false;
    if (c == '#') {
      while (i + 1 < s.size() && s[i + 1] != '\n') ++i;
    } else if (c == '"' || c == '\'') {
      const std::string close(s.compare(i, 3, std::string(3, c)) == 0 ? 3 : 1, c);
      for (i += close.size(); i < s.size() && s.compare(i, close.size(), close) != 0; ++i) {
        if (c == '"' && s[i] == '\\' && i + 1 < s.size()) ++i;  // escaped character
        if (s[i] == '\n') ++line;
      }
      i += close.size() - 1;
    } else if (c == '[' || c == '{') {
      open += c;
      if (static_cast<int>(open.size()) > kMaxNesting)
        return {line,
                "arrays or inline tables nested more than " + std::to_string(kMaxNesting) +
                    " levels deep",
                kShallow};
      if (c == '{') {
        in_key = true;
        dots = 0;
      } else if (header) {
        in_key = true;
      } else if (!(s[i - 1] == '[' && open.size() == 2)) {  // "[[" keeps a header a header
        in_key = false;
      }
    } else if (c == ']' || c == '}') {
      if (!open.empty()) open.pop_back();
    } else if (c == ',') {
      if (!open.empty() && open.back() == '{') {
        in_key = true;
        dots = 0;
      }
    } else if (c == '=') {
      in_key = false;
    } else if (c == '.' && in_key && ++dots > kMaxKeyDots) {
      return {line, "a key with more than " + std::to_string(kMaxKeyDots + 1) + " dotted parts",
              kShallow};
    }
  }
  return {};
}

TomlTextProblem FindUnsafeTomlText(const std::string& text) {
  if (TomlTextProblem p = FindInvalidUtf8(text); p.line > 0) return p;
  return FindTooDeep(text);
}

}  // namespace tehl::internal

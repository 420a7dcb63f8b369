// Checks made on the text of an input file before it is handed to the TOML parser.
//
// The parser (toml11 3.7) has inputs it does not survive: invalid UTF-8 inside a string sends
// its error path out of the string's buffer, deep nesting overflows the stack, and a key with
// thousands of dotted parts takes minutes. No tehl file needs any of these, so they are found
// here first and reported as syntax problems with their line.
#pragma once

#include <string>

namespace tehl::internal {

/// What the text check found; line 0 means nothing.
struct TomlTextProblem {
  int line = 0;         ///< 1-based line of the first problem [-]
  std::string what;     ///< the problem, e.g. "byte 0xff at column 7 is not UTF-8"
  std::string allowed;  ///< what the text may hold instead
};

/// The first byte sequence that is not UTF-8 (RFC 3629: no overlong forms, no surrogates,
/// nothing above U+10FFFF). TOML documents must be UTF-8 throughout, comments included.
TomlTextProblem FindInvalidUtf8(const std::string& text);

/// Arrays or inline tables nested more than 32 deep, or a key or table header with more than
/// 33 dotted parts. Strings and comments are skipped; what is not TOML is left to the parser.
TomlTextProblem FindTooDeep(const std::string& text);

/// Both checks, UTF-8 first.
TomlTextProblem FindUnsafeTomlText(const std::string& text);

}  // namespace tehl::internal

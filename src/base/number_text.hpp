// Numbers as text, the same in every locale (std::to_chars / std::from_chars): a library
// user's setlocale never turns a decimal point into a comma inside a result file, nor
// breaks reading one back. Below every layer. Private to src/.
#pragma once

#include <string>
#include <string_view>

namespace tehl::internal {

std::string FormatReal(double x);   // shortest round-trip, valid TOML float ("1.0", "2.5e-06")
std::string FormatShort(double x);  // 3 significant digits (as "%.3g"), for messages

// Strict: the whole of `text` (an optional leading '+' allowed) is one number in the C
// locale's notation, finite unless `allow_non_finite` (then "nan", "inf" too). false
// otherwise, `out` untouched.
bool ParseReal(std::string_view text, double* out, bool allow_non_finite = false);

// ParseReal or std::runtime_error naming `what` and the text (files tehl wrote itself).
double ParseRealOrThrow(std::string_view text,
                        const std::string& what,
                        bool allow_non_finite = false);

}  // namespace tehl::internal

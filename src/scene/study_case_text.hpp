// Case text of a study scene: the base case as run (Document::ToToml, one `[section]` header
// and one `key = value  # [unit]` line per key) with keys replaced or added. Private to src/.
#pragma once

#include <string>
#include <vector>

namespace tehl::internal {

struct CaseOverride {
  std::string key;      // dotted case key, "surfaces.surface1.amplitude_m"
  std::string literal;  // TOML literal of the new value
};

// Returns `case_text` with each override applied: the key's line in its section replaced,
// or added at the end of the section, or the section appended when the text has none.
std::string ApplyCaseOverrides(const std::string& case_text,
                               const std::vector<CaseOverride>& overrides);

// "surfaces.surface1.amplitude_m" -> {"surfaces.surface1", "amplitude_m"}.
std::pair<std::string, std::string> SplitCaseKey(const std::string& dotted);

}  // namespace tehl::internal

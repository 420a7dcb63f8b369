// Case text derived from another case (a study's scenes, the [contact] case of a point of a
// gear's path): the case as run (Document::ToToml, one `[section]` header and one
// `key = value  # [unit]` line per key) with keys replaced or added and sections removed.
// Private to src/.
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

// Returns `case_text` without the named sections (header and keys; "gear" does not remove
// "gear.pinion").
std::string RemoveCaseSections(const std::string& case_text,
                               const std::vector<std::string>& sections);

class Document;
// Paths in a case are relative to the case file; a derived case lives elsewhere, so it gets
// them (lubricant file, roughness profiles) resolved relative to `base_path` as absolute
// paths. Keys already in `overrides` are resolved as overridden.
void AddPathOverrides(const Document& base,
                      const std::string& base_path,
                      std::vector<CaseOverride>* overrides);

// "surfaces.surface1.amplitude_m" -> {"surfaces.surface1", "amplitude_m"}.
std::pair<std::string, std::string> SplitCaseKey(const std::string& dotted);

}  // namespace tehl::internal

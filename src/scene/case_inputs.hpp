// The files a case reads besides itself: its lubricant file and its measured surface
// profiles. A result depends on their contents as much as on the case text, so the
// fingerprints that decide whether a checkpoint or a study scene's result may be reused
// (`--resume`) cover them too. Private to src/.
#pragma once

#include <string>

#include "base/schema.hpp"

namespace tehl::internal {

// "<path>\n<contents>\n" for the lubricant file and each profile_file of `doc` (resolved as a
// run resolves them; "<path>\n(unreadable)\n" for one that cannot be read), in a fixed order.
std::string ReferencedInputsText(const Document& doc);

// The case file at `case_path` followed by ReferencedInputsText of it (a file that does not
// parse contributes its text only).
std::string CaseWithInputsText(const std::string& case_path);

}  // namespace tehl::internal

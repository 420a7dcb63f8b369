// Where tehl's helper scripts (scripts/*.py) are: $TEHL_SCRIPT_DIR, then share/tehl/scripts
// beside the installed library or program, then the source tree, then the configured
// install prefix (data_dir.hpp). Private to src/.
#pragma once

#include <string>

namespace tehl::internal {

// Full path of the script `name` (e.g. "plot_cycle.py"), or "" when none of the folders has it.
std::string FindScript(const std::string& name);

}  // namespace tehl::internal

// Runs one of tehl's plotting scripts (scripts/*.py, found by internal::FindScript) with the
// Python that has matplotlib and h5py: $TEHL_PYTHON when set, else Debian's /usr/bin/python3
// (python3-matplotlib, python3-h5py), else the first python3 on PATH.
#pragma once

#include <string>
#include <vector>

namespace tehl::cli {

// The exit code for the command: kExitOk when the script succeeded, kExitBadInput when it
// reported bad input (its exit code 2) or Python could not be started (named, with what it
// needs), kExitInternal for a missing script or any other failure. `command` prefixes the
// messages ("tehl plot").
int RunPythonScript(const std::string& command,
                    const std::string& script_name,
                    const std::vector<std::string>& args);

}  // namespace tehl::cli

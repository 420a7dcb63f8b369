// A text file written atomically: to `path` + ".part", then renamed, so that a file under its
// final name is always complete (DESIGN.md: nothing is lost). Private to src/.
#pragma once

#include <string>

namespace tehl::internal {

// Creates the parent folders, writes `text` to path + ".part" and renames it to `path`.
// A file that cannot be written is the folder's or the disk's fault, not a defect: it throws
// std::filesystem::filesystem_error naming the path and the cause (the command line reports it
// with exit code 2), and leaves no temporary file behind.
void WriteTextAtomically(const std::string& path, const std::string& text);

}  // namespace tehl::internal

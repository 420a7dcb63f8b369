// FFTW wisdom kept across processes, on request. FFTW_MEASURE planning of one grid size costs
// 0.15 s (513 nodes) to 8.6 s (16385 nodes) in every process (docs/performance.md, "One-off
// cost"); FFTW's wisdom records the plans it chose. With the environment variable
// TEHL_FFTW_WISDOM=FILE, the first measured planning of a process imports FILE (if it
// exists), and a planning that measured something new writes the process's wisdom back to
// FILE (through a temporary file renamed over it, so that concurrent processes never read a
// half-written file; the last writer wins). Unset or empty: nothing is read or written.
// Wisdom is only valid for the FFTW build and the machine that made it; FFTW refuses wisdom of
// another FFTW version on import.
// The callers hold FftwPlannerMutex() (fftw_planner.hpp): FFTW's wisdom is planner state.
#pragma once

#include <string>

namespace tehl::internal {

// TEHL_FFTW_WISDOM ("" = off).
std::string WisdomFile();
// Imports WisdomFile() at the first call that finds it set (later calls do nothing).
void ImportWisdomOnce();
// Merges the wisdom in `path` into the process's; false if it is missing or not FFTW wisdom.
bool ImportWisdom(const std::string& path);
// Writes the process's wisdom to `path` (temporary file, then renamed); false on failure.
bool ExportWisdom(const std::string& path);

}  // namespace tehl::internal

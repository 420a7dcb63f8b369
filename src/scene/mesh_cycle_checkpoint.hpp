// Checkpoints of a mesh cycle: everything a killed run needs to continue to the same result
// (docs/results.md, "Checkpoints and --resume"): the rows and profiles done so far, the film
// state of the last step and the solver's transient history. A small binary file
// (`NAME.checkpoint`, little-endian doubles, length-prefixed arrays and strings, a version
// tag and a fingerprint of the case as run), written to a temporary name and renamed, so a
// checkpoint on disk is always complete. Private to src/scene.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "tehl/ehl/line_contact_solver.hpp"
#include "tehl/scene/mesh_cycle_scene.hpp"

namespace tehl::internal {

struct MeshCycleCheckpoint {
  std::uint64_t fingerprint = 0;  // of the case text as run (defaults filled)
  int next_step = 0;              // index into the step positions of the next step to solve
  double elapsed_s = 0;           // wall time of the run before the checkpoint [s]
  MeshCycleResult result;         // rows and profiles so far
  FilmState state;                // the film at the last step done
  LineContactSolver::TransientHistory history;
};

std::uint64_t CaseFingerprint(const std::string& case_text);

// Writes atomically (path + ".part", then rename). Throws std::runtime_error on I/O failure.
void WriteCheckpoint(const std::string& path, const MeshCycleCheckpoint& c);

// Reads a checkpoint; nullopt when the file is missing, damaged or of another version.
std::optional<MeshCycleCheckpoint> ReadCheckpoint(const std::string& path);

}  // namespace tehl::internal

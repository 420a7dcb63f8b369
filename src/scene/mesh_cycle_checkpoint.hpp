// Checkpoints of a mesh cycle: everything a killed run needs to continue to the same result
// (docs/results.md, "Checkpoints and --resume"). Two files:
//  - NAME.checkpoint: small, rewritten at each checkpoint (to a temporary name, then renamed,
//    so the file on disk is always complete): a version tag, a fingerprint of the case as run,
//    the next step, the film state of the last step, the solver's transient history, and how
//    much of the journal below is committed (its identity, length and row counts).
//  - NAME.checkpoint.rows: an append-only journal of the /cycle rows and profiles; each
//    checkpoint appends only the rows solved since the one before, so a checkpoint costs the
//    same at step 10 and at step 2000 (rewriting every row at every checkpoint made the
//    checkpoints of a 2386-step rough cycle a fifth of its run time). Bytes past the committed
//    length (a run killed between the append and the rename) are ignored, and cut off when
//    the run is continued.
// Little-endian doubles and 64-bit integers, length-prefixed arrays and strings. Integrity:
// NAME.checkpoint ends with a 64-bit FNV-1a checksum of all its bytes before it, and records
// the FNV-1a checksum of the committed journal, so a byte changed in either file (a disk or
// copy error, an edit by hand) keeps the checkpoint from being used rather than giving a
// wrong result. The magics end in the format's version (TEHLCKPA, TEHLROW5). Private to
// src/scene.
#pragma once

#include <array>
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
  MeshCycleResult result;         // rows and profiles so far (from the journal)
  FilmState state;                // the film at the last step done
  LineContactSolver::TransientHistory history;
  std::uint64_t journal_id = 0;        // identity of the journal the rows came from
  std::int64_t journal_bytes = 0;      // its committed length [bytes]
  std::uint64_t journal_checksum = 0;  // FNV-1a of its committed bytes
};

std::uint64_t CaseFingerprint(const std::string& case_text);

// The journal beside a checkpoint file.
std::string CheckpointRowsPath(const std::string& checkpoint_path);

// Writes the checkpoints of one run.
class CheckpointWriter {
 public:
  explicit CheckpointWriter(std::string checkpoint_path);

  // The run goes on from `c`, as ReadCheckpoint returned it: its rows stay in the journal.
  void ContinueFrom(const MeshCycleCheckpoint& c);

  // Appends the rows and profiles of `r` that are not in the journal yet, then replaces
  // NAME.checkpoint. The first write of a run that did not continue starts a new journal.
  // Throws std::runtime_error on I/O failure.
  void Write(std::uint64_t fingerprint,
             int next_step,
             double elapsed_s,
             const MeshCycleResult& r,
             const FilmState& state,
             const LineContactSolver::TransientHistory& history);

  // Deletes both files (the result is complete).
  void Remove() const;

 private:
  std::string path_;
  std::uint64_t journal_id_ = 0;
  std::int64_t journal_bytes_ = 0;         // 0: no journal of this run yet
  std::uint64_t journal_checksum_ = 0;     // FNV-1a of the journal's committed bytes
  std::array<std::int64_t, 7> written_{};  // steps, then the six profile arrays, on disk
};

// Reads a checkpoint and its journal; nullopt when there is none, or when it cannot be used:
// either file damaged (a checksum that does not match, a layout that does not parse, a
// non-finite value in the film state or solver history), of another version, not a file (a
// folder in its place), or the two not belonging together. `problem`, when given, receives
// why (empty when there is no checkpoint). Never throws.
std::optional<MeshCycleCheckpoint> ReadCheckpoint(const std::string& path,
                                                  std::string* problem = nullptr);

// Where a resumed run starts: the first step to solve (1: the steady film at the start of
// the cycle comes first) and the wall time spent before [s].
struct ResumePoint {
  size_t first_step = 1;
  double elapsed_s = 0;
  int resumed_from_step = 0;  // 0: not resumed
};

// Continues `r` (rows and profiles), `state` and `solver`'s time history, and `writer`'s
// journal, from the checkpoint at `path` when it is of this run: the same `fingerprint`, a
// next step inside the plan of `films` films (steps + 1), and a film of `grid_nodes` nodes.
// Otherwise leaves them and says on stderr why no checkpoint is used (a damaged or unusable
// one always; a missing one unless `quiet`).
ResumePoint ResumeFromCheckpoint(const std::string& path,
                                 std::uint64_t fingerprint,
                                 size_t films,
                                 int grid_nodes,
                                 bool quiet,
                                 CheckpointWriter* writer,
                                 MeshCycleResult* r,
                                 FilmState* state,
                                 LineContactSolver* solver);

}  // namespace tehl::internal

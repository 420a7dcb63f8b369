// A time step of a transient run (mesh cycle, [contact] time tables) with the fallback of
// [numerics] failed_step = "steady_restart": when the step does not converge (after the
// solver's own substeps), the film at the step's time is solved as a steady film from the
// state before the step (if that fails too, once more cold: grid sequencing from the coarse
// grid, independent of that state), and the transient marches on from it (BeginTransient:
// BDF1 for the next step, then the case's scheme). The step is flagged with the failure it
// replaced, so a result never passes a steady film off as the transient one.
//
// Why: a transient step can fail where the steady film does not, e.g. the Newtonian thermal
// film right after B of the seed 004 cycle on 2049 nodes, whose squeeze spike heats faster
// than the coupling can follow (docs/thermal.md, "The seed 004 cycle at full resolution");
// stopping there loses the rest of the path, while the squeeze transient it drops has
// decayed within a step or two (the steps after the restart match the transient ones).
#pragma once

#include <string>

#include "tehl/ehl/line_contact_solver.hpp"

namespace tehl::internal {

struct MarchedStep {
  // The step failed, its steady films too, and skipping was asked for: `state` holds the failed
  // attempt's best iterate (for the step's row); the run goes on from `resume` and the solver
  // history `resume_history` (the last converged level, which ResumeAfterSkip restores).
  bool skipped = false;
  FilmState resume;
  LineContactSolver::TransientHistory resume_history;
  // The step's summary, or that of the steady solve that replaced it (its wall time, total,
  // GMRES and coupling iterations then include the failed attempt, and `substeps` is the
  // attempt's: 4 after the solver's whole ladder).
  LineContactSolver::Summary summary;
  // Empty: the transient step converged (or failed with restart off, or both steady solves
  // failed too: then `summary` is the step's with their cost added, its message naming all
  // three failures). Otherwise
  // the failed step's termination and message.
  std::string restart_reason;
};

// Advances `state` by dt_s to the conditions c (LineContactSolver::Step), with the steady
// fallback above when `steady_restart` is true. After a restart the solver's transient
// history starts at the steady film. With `skip` (failed_step = "steady_restart_or_skip"),
// a step whose steady films fail too comes back `skipped`; the next step then spans the
// skipped ones (its dt from the resumed level's time).
MarchedStep StepOrRestart(LineContactSolver& solver,
                          const ContactConditions& c,
                          double dt_s,
                          FilmState* state,
                          bool steady_restart,
                          bool skip = false,
                          const ContactConditions* c_start = nullptr);

// After a skipped step has been recorded: the state and the solver history of the last
// converged level again.
void ResumeAfterSkip(LineContactSolver& solver, MarchedStep* step, FilmState* state);

// A run that skips failed steps stops once this many in a row have failed: the film can then
// no longer be followed, and every further attempt costs as much as a failed step.
constexpr int kMaxSkippedInARow = 3;

}  // namespace tehl::internal

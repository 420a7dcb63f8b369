#include "scene/step_restart.hpp"

#include <cmath>
#include <optional>
#include <utility>

namespace tehl::internal {
namespace {

// Adds the wall time and the iterations of `from` to `to`.
void AddCost(const LineContactSolver::Summary& from, LineContactSolver::Summary* to) {
  to->wall_time_s += from.wall_time_s;
  to->total_iterations += from.total_iterations;
  to->krylov_iterations += from.krylov_iterations;
  to->coupling_iterations += from.coupling_iterations;
}

// The row of a failed step holds the film the solver was left with (time stepping gives back
// the film it started from, or the last substep it reached): its load error is that film's,
// |integral p dx - w| / w against the step's load.
void SetLoadErrorOfTheFilmLeft(const LineContactSolver& solver,
                               const ContactConditions& c,
                               const FilmState& s,
                               LineContactSolver::Summary* sum) {
  if (s.p_pa.size() != solver.grid().size() || !(c.load_n_per_m > 0)) return;
  sum->load_error = std::abs(solver.grid().dx_m() * s.p_pa.sum() - c.load_n_per_m) / c.load_n_per_m;
}

}  // namespace

MarchedStep StepOrRestart(LineContactSolver& solver,
                          const ContactConditions& c,
                          double dt_s,
                          FilmState* state,
                          bool steady_restart,
                          bool skip,
                          const ContactConditions* c_start) {
  std::optional<FilmState> before;
  LineContactSolver::TransientHistory history;
  if (steady_restart) {
    before = *state;
    history = solver.SaveTransient();
  }
  const ContactConditions& c_prev = history.c_prev;  // the conditions before the step
  MarchedStep out;
  out.summary = solver.Step(c, dt_s, state, c_start);
  if (out.summary.usable()) return out;
  if (!steady_restart) {
    SetLoadErrorOfTheFilmLeft(solver, c, *state, &out.summary);
    return out;
  }
  // The steady film at the step's time: its surfaces moved on as the step would have moved
  // them (rough surfaces are sampled at their travel; LineContactSolver::Step's trapezoid).
  FilmState steady = *before;
  steady.time_s = before->time_s + dt_s;
  steady.travel1_m = before->travel1_m + 0.5 * dt_s * (c_prev.u1_m_s + c.u1_m_s);
  steady.travel2_m = before->travel2_m + 0.5 * dt_s * (c_prev.u2_m_s + c.u2_m_s);
  // The state before the step was solved for the previous level's conditions (also after a
  // --resume, whose restored state does not carry them): SolveSteady then starts from it
  // scaled by Hertz similarity, as the step itself did (LineContactSolver::Step).
  steady.solved_for = c_prev;
  LineContactSolver::Summary s = solver.SolveSteady(c, &steady);
  if (!s.usable()) {
    // The state before the step can be a poor start: a squeezed film whose transient pressure
    // spike the steady film does not have (the thermal seed 004 cycle on 4097 nodes, right
    // after B). A cold solve (grid sequencing from the coarse grid, the isothermal film before
    // the coupling) does not depend on it.
    FilmState cold;
    cold.time_s = steady.time_s;
    cold.travel1_m = steady.travel1_m;
    cold.travel2_m = steady.travel2_m;
    LineContactSolver::Summary sc = solver.SolveSteady(c, &cold);
    AddCost(s, &sc);
    if (!sc.usable()) {
      out.summary.message +=
          "; the steady film at this time did not converge either, from the "
          "state before the step (" +
          ToString(s.termination) + ": " + s.message + ") nor cold (" + ToString(sc.termination) +
          ": " + sc.message + ")" +
          (skip ? "" : "; [numerics] failed_step = \"steady_restart_or_skip\" goes on past it");
      AddCost(sc, &out.summary);
      SetLoadErrorOfTheFilmLeft(solver, c, *state, &out.summary);
      if (skip) {
        out.skipped = true;
        out.resume = std::move(*before);
        out.resume_history = std::move(history);
      }
      return out;
    }
    steady = std::move(cold);
    s = std::move(sc);
  }
  *state = std::move(steady);
  solver.BeginTransient(c, *state);
  out.restart_reason = ToString(out.summary.termination) + ": " + out.summary.message;
  // The step's cost includes the failed attempt: its time, iterations and substeps.
  AddCost(out.summary, &s);
  s.substeps = out.summary.substeps;
  out.summary = std::move(s);
  return out;
}

void ResumeAfterSkip(LineContactSolver& solver, MarchedStep* step, FilmState* state) {
  *state = std::move(step->resume);
  solver.RestoreTransient(step->resume_history);
}

}  // namespace tehl::internal

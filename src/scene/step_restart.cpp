#include "scene/step_restart.hpp"

#include <optional>
#include <utility>

namespace tehl::internal {

MarchedStep StepOrRestart(LineContactSolver& solver,
                          const ContactConditions& c,
                          double dt_s,
                          FilmState* state,
                          bool steady_restart) {
  std::optional<FilmState> before;
  ContactConditions c_prev;  // the conditions of the level before the step
  if (steady_restart) {
    before = *state;
    c_prev = solver.SaveTransient().c_prev;
  }
  MarchedStep out;
  out.summary = solver.Step(c, dt_s, state);
  if (out.summary.usable() || !steady_restart) return out;
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
    out.summary.message += "; the steady film at this time did not converge either (" +
                           ToString(s.termination) + ": " + s.message + ")";
    return out;
  }
  *state = std::move(steady);
  solver.BeginTransient(c, *state);
  out.restart_reason = ToString(out.summary.termination) + ": " + out.summary.message;
  // The step's cost includes the failed attempt: its time, iterations and substeps.
  s.wall_time_s += out.summary.wall_time_s;
  s.total_iterations += out.summary.total_iterations;
  s.krylov_iterations += out.summary.krylov_iterations;
  s.coupling_iterations += out.summary.coupling_iterations;
  s.substeps = out.summary.substeps;
  out.summary = std::move(s);
  return out;
}

}  // namespace tehl::internal

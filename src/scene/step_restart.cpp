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
  if (steady_restart) before = *state;
  MarchedStep out;
  out.summary = solver.Step(c, dt_s, state);
  if (out.summary.usable() || !steady_restart) return out;
  FilmState steady = *before;
  LineContactSolver::Summary s = solver.SolveSteady(c, &steady);
  if (!s.usable()) {
    out.summary.message += "; the steady film at this time did not converge either (" +
                           ToString(s.termination) + ": " + s.message + ")";
    return out;
  }
  steady.time_s = before->time_s + dt_s;
  *state = std::move(steady);
  solver.BeginTransient(c, *state);
  out.restart_reason = ToString(out.summary.termination) + ": " + out.summary.message;
  s.wall_time_s += out.summary.wall_time_s;
  out.summary = std::move(s);
  return out;
}

}  // namespace tehl::internal

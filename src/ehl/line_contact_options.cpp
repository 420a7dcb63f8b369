// The line-contact solver's names, options, film state and summary: the string forms of its
// enums, the film's derived quantities, the validation of Options and the one-line report
// (include/tehl/ehl/line_contact_solver.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "base/number_text.hpp"
#include "tehl/ehl/line_contact_solver.hpp"
#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl {

std::string ToString(LinearSolverKind k) {
  switch (k) {
    case LinearSolverKind::kAuto:
      return "auto";
    case LinearSolverKind::kDense:
      return "dense";
    case LinearSolverKind::kNewtonKrylov:
      return "newton_krylov";
    case LinearSolverKind::kReusedLu:
      return "reused_lu";
  }
  return "?";
}
LinearSolverKind LinearSolverKindFromString(const std::string& s) {
  for (auto k : {LinearSolverKind::kAuto, LinearSolverKind::kDense, LinearSolverKind::kNewtonKrylov,
                 LinearSolverKind::kReusedLu})
    if (ToString(k) == s) return k;
  throw InputError(InputProblem{"", 0, "linear_solver", "\"" + s + "\"", "unknown solver",
                                "auto, dense, newton_krylov, reused_lu"});
}
std::string ToString(TimeScheme s) { return s == TimeScheme::kBdf1 ? "bdf1" : "bdf2"; }
TimeScheme TimeSchemeFromString(const std::string& s) {
  if (s == "bdf1") return TimeScheme::kBdf1;
  if (s == "bdf2") return TimeScheme::kBdf2;
  throw InputError(
      InputProblem{"", 0, "time_scheme", "\"" + s + "\"", "unknown scheme", "bdf1, bdf2"});
}
std::string ToString(LineContactSolver::Termination t) {
  using T = LineContactSolver::Termination;
  switch (t) {
    case T::kConverged:
      return "converged";
    case T::kMaxIterations:
      return "max_iterations";
    case T::kLineSearchFailed:
      return "line_search_failed";
    case T::kLinearSolverFailed:
      return "linear_solver_failed";
    case T::kInvalidInput:
      return "invalid_input";
    case T::kCouplingNotConverged:
      return "coupling_not_converged";
  }
  return "?";
}

double FilmState::MinFilm() const {
  if (!h_m.size()) return 0.0;
  Eigen::Index i;
  const double hmin = h_m.minCoeff(&i);
  if (i == 0 || i == h_m.size() - 1) return hmin;
  // The parabola through the smallest node and its neighbours: h_min between nodes. A
  // parabola that dips below zero between positive nodes (a film a few nm thin at a sharp
  // asperity) is not resolved by the grid: the smallest node is the answer then.
  const double a = h_m[i - 1], b = h_m[i + 1], curv = a - 2 * hmin + b;
  const double vertex = curv > 0 ? hmin - (b - a) * (b - a) / (8 * curv) : hmin;
  return vertex >= 0 || hmin < 0 ? vertex : hmin;
}
double FilmState::MaxPressure() const { return p_pa.size() ? p_pa.maxCoeff() : 0.0; }
double FilmState::CentralFilm(const UniformGrid& g) const {
  if (!h_m.size()) return 0.0;
  const double s = (0.0 - g.x_start_m()) / g.dx_m();
  const int i = std::clamp(static_cast<int>(std::floor(s)), 0, g.size() - 2);
  const double f = std::clamp(s - i, 0.0, 1.0);
  return (1 - f) * h_m[i] + f * h_m[i + 1];
}

std::vector<std::string> LineContactSolver::Options::Validate() const {
  std::vector<std::string> bad;
  auto rule = [&](bool ok, const char* field, double v, const char* c) {
    if (!ok)
      bad.push_back(std::string("LineContactSolver::Options::") + field + " = " +
                    (v == std::trunc(v) && std::abs(v) < 1e15
                         ? std::to_string(static_cast<long long>(v))
                         : internal::FormatReal(v)) +
                    " violates " + c);
  };
  rule(upwind_order == 1 || upwind_order == 2, "upwind_order", upwind_order, "1 or 2");
  rule(tolerance > 0 && tolerance < 1, "tolerance", tolerance, "in (0, 1)");
  rule(time_tolerance >= 0 && std::isfinite(time_tolerance), "time_tolerance", time_tolerance,
       ">= 0 (0 = off)");
  rule(max_iterations >= 1, "max_iterations", max_iterations, ">= 1");
  rule(dense_max_nodes >= 5, "dense_max_nodes", dense_max_nodes, ">= 5");
  rule(gmres_restart >= 2, "gmres_restart", gmres_restart, ">= 2");
  rule(gmres_max_iterations >= 1, "gmres_max_iterations", gmres_max_iterations, ">= 1");
  rule(reused_lu_max_gmres >= 1, "reused_lu_max_gmres", reused_lu_max_gmres, ">= 1");
  rule(preconditioner_band >= 0, "preconditioner_band", preconditioner_band, ">= 0");
  rule(preconditioner_coarse_pressures >= 0, "preconditioner_coarse_pressures",
       preconditioner_coarse_pressures, ">= 0");
  rule(preconditioner_inlet_hats >= 1, "preconditioner_inlet_hats", preconditioner_inlet_hats,
       ">= 1");
  rule(preconditioner_outlet_refresh >= 0, "preconditioner_outlet_refresh",
       preconditioner_outlet_refresh, ">= 0");
  rule(max_continuation_stages >= 0, "max_continuation_stages", max_continuation_stages, ">= 0");
  rule(min_step_fraction > 0 && min_step_fraction <= 1, "min_step_fraction", min_step_fraction,
       "in (0, 1]");
  rule(film_nodes >= 3, "film_nodes", film_nodes, ">= 3");
  rule(thermal_tolerance_k > 0, "thermal_tolerance_k", thermal_tolerance_k, "> 0");
  rule(coupling_pressure_tolerance > 0, "coupling_pressure_tolerance", coupling_pressure_tolerance,
       "> 0");
  rule(max_coupling_iterations >= 1, "max_coupling_iterations", max_coupling_iterations, ">= 1");
  rule(max_coupling_iterations_converging >= 1, "max_coupling_iterations_converging",
       max_coupling_iterations_converging, ">= 1");
  rule(thermal_relaxation > 0 && thermal_relaxation <= 1, "thermal_relaxation", thermal_relaxation,
       "in (0, 1]");
  rule(coupling_newton_after >= 0, "coupling_newton_after", coupling_newton_after, ">= 0");
  rule(coarse_grid_nodes >= 5, "coarse_grid_nodes", coarse_grid_nodes, ">= 5");
  const int solver = static_cast<int>(linear_solver);
  rule(solver >= static_cast<int>(LinearSolverKind::kAuto) &&
           solver <= static_cast<int>(LinearSolverKind::kReusedLu),
       "linear_solver", solver, "a LinearSolverKind");
  const int scheme = static_cast<int>(time_scheme);
  rule(scheme == static_cast<int>(TimeScheme::kBdf1) ||
           scheme == static_cast<int>(TimeScheme::kBdf2),
       "time_scheme", scheme, "a TimeScheme");
  return bad;
}

std::string LineContactSolver::Summary::BriefReport() const {
  std::ostringstream o;
  o << ToString(termination) << ": " << total_iterations << " Newton iterations";
  if (continuation_stages) o << " (" << continuation_stages << " continuation stages)";
  if (krylov_iterations) o << ", " << krylov_iterations << " GMRES iterations";
  if (substeps > 1) o << ", " << substeps << " substeps";
  // Without the energy equation (an isothermal Ree-Eyring film) the balance is not computed
  // (-1) and the coupling is the pressure's with the Eyring factor.
  if (coupling_iterations && energy_balance_error >= 0)
    o << ", " << coupling_iterations << " thermal coupling iterations (last dT "
      << temperature_change_k << " K, energy balance " << energy_balance_error << ")";
  else if (coupling_iterations)
    o << ", " << coupling_iterations << " coupling iterations with the Eyring factor";
  if (coupling_newton_iterations)
    o << ", " << coupling_newton_iterations << " coupling Newton steps";
  if (temperature_backoffs) o << ", " << temperature_backoffs << " temperature step halvings";
  o << ", residual " << residual << ", load error " << load_error << ", " << linear_solver << ", "
    << wall_time_s << " s";
  if (!usable()) o << ": " << message;
  if (usable() && outlet_cut)
    o << "; the pressure is still positive next to the grid's outlet end: the grid cuts the "
         "film off (size it for a larger half-width)";
  return o.str();
}

}  // namespace tehl

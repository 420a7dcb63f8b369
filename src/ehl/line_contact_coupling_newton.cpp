// LineContactSolver::Impl::NewtonCoupling: Newton-Krylov on the thermal (and Ree-Eyring)
// coupling map x -> G(x), x = (T[, w log f]): one alternation step of the pressure and energy
// solves without relaxation (docs/thermal.md, "Coupling").
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "ehl/film_field.hpp"
#include "ehl/fixed_point_newton.hpp"
#include "ehl/line_contact_impl.hpp"

namespace tehl {
namespace {
using internal::TimeDerivative;
// Newton on the thermal coupling: each map evaluation's energy solve tolerance and the
// finite-difference step of its directional derivatives [K] (noise / step ~ 1e-4).
constexpr double kCouplingMapToleranceK = 1e-5;
constexpr double kCouplingFdStepK = 0.1;
constexpr double kCouplingMapPressureTolerance = 1e-11;  // [-]
}  // namespace

LineContactSolver::Impl::CouplingNewton LineContactSolver::Impl::NewtonCoupling(
    const ContactConditions& c,
    const TimeDerivative& td,
    const FilmState* previous,
    double dt_s,
    FilmState* s) {
  CouplingNewton out;
  const Eigen::Index m = field_->film_temperature().size();
  const bool eyring = eff_.non_newtonian;
  FilmState work = *s;
  Eigen::MatrixXd image;
  // G(x), x = (T[, w log f]): the pressure solved with the film at x; in Ree-Eyring runs the
  // factor of that pressure at T (w log f') and the energy equation's temperature with it
  // (T'): one alternation step without relaxation or mixing. The field is left at x.
  const internal::FixedPointMap map = [&](const Eigen::VectorXd& x, Eigen::VectorXd* g) {
    field_->SetCouplingState(x);
    FilmState trial = work;
    const double keep_tolerance = opt_.tolerance;
    opt_.tolerance = std::min(opt_.tolerance, kCouplingMapPressureTolerance);
    out.pressure = Solve(c, td, &trial);
    opt_.tolerance = keep_tolerance;
    if (!out.pressure.usable()) return false;
    if (eyring) field_->UpdateRheology(c, trial, 1.0);
    internal::FilmField::EnergyUpdate e;
    try {
      e = field_->MapTemperature(c, trial, previous, dt_s, kCouplingMapToleranceK, &image);
    } catch (const std::exception&) {
      e.ok = false;
    }
    if (e.ok) {
      *g = field_->CouplingState();
      g->head(m) = Eigen::Map<const Eigen::VectorXd>(image.data(), image.size());
    }
    field_->SetCouplingState(x);
    if (!e.ok) return false;
    out.balance = e.summary.balance.RelativeError();
    out.energy = e.summary.balance;
    work = trial;
    return true;
  };
  internal::FixedPointNewtonOptions o;
  o.tolerance = opt_.thermal_tolerance_k;
  o.fd_step = kCouplingFdStepK;
  field_->CouplingBounds(c.temperature_k, &o.lower_bounds, &o.upper_bounds);
  Eigen::VectorXd x = field_->CouplingState();
  out.result = internal::SolveFixedPoint(map, o, &x);
  if (std::getenv("TEHL_DEBUG_COUPLING")) {
    std::fprintf(stderr, "coupling Newton: %s, %d steps, %d GMRES, %d maps, residual %g K:",
                 out.result.converged ? "converged" : "failed", out.result.newton_iterations,
                 out.result.krylov_iterations, out.result.map_evaluations, out.result.residual);
    for (double h : out.result.history) std::fprintf(stderr, " %g", h);
    std::fprintf(stderr, " %s\n", out.result.message.c_str());
  }
  // The field holds x and `work` the pressure at x (the map was last evaluated there).
  *s = work;
  return out;
}

}  // namespace tehl

#include "tehl/ehl/line_contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "base/number_text.hpp"
#include "ehl/line_contact_impl.hpp"
#include "ehl/newton_system.hpp"
#include "tehl/ehl/film_thickness_formulas.hpp"
#include "tehl/ehl/surface_roughness.hpp"
#include "tehl/error.hpp"
#include "tehl/lubricant/lubricant.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {
using internal::FluidLaws;
using internal::TimeDerivative;

// The grid a solver is built on: a default-constructed UniformGrid is empty (the checked
// constructor and AroundHertz give n >= 5).
const UniformGrid& UsableGrid(const UniformGrid& grid) {
  if (grid.size() < 5 || !(grid.dx_m() > 0) || !std::isfinite(grid.dx_m()))
    throw InputError(InputProblem{"", 0, "grid", std::to_string(grid.size()) + " nodes",
                                  "a line contact needs a grid of at least 5 nodes (a "
                                  "default-constructed UniformGrid is empty)",
                                  "UniformGrid(x_start_m, x_end_m, n) or "
                                  "UniformGrid::AroundHertz(b, n), n >= 5"});
  return grid;
}

// "LineContactSolver::Options::field = value violates allowed" (Options::Validate) as a
// problem with its key, value and what is allowed.
InputProblem OptionsProblem(const std::string& message) {
  const size_t eq = message.find(" = "), violates = message.find(" violates ");
  if (eq == std::string::npos || violates == std::string::npos || violates < eq)
    return {"", 0, "LineContactSolver::Options", "", message, ""};
  return {"",
          0,
          message.substr(0, eq),
          message.substr(eq + 3, violates - eq - 3),
          "out of range",
          message.substr(violates + 10)};
}
}  // namespace

// ---------------------------------------------------------------------------------------
LineContactSolver::Impl::Impl(const UniformGrid& grid,
                              double e_prime,
                              const Lubricant& lub,
                              const FilmEffects& eff,
                              const Options& opt,
                              std::shared_ptr<const SurfaceShape> s1,
                              std::shared_ptr<const SurfaceShape> s2,
                              const ContactSolids& solids)
    : grid_(UsableGrid(grid)),
      e_prime_(e_prime),
      lub_(lub),
      eff_(eff),
      opt_(opt),
      s1_(std::move(s1)),
      s2_(std::move(s2)),
      solids_(solids),
      sys_(grid.size(), grid.dx_m(), opt.upwind_order) {
  ProblemList bad;
  for (const auto& m : opt.Validate()) bad.Add(OptionsProblem(m));
  if (!(e_prime > 0) || !std::isfinite(e_prime))
    bad.Add({"", 0, "e_prime_pa", internal::FormatReal(e_prime), "must be finite and > 0",
             "E' > 0 [Pa], 2/E' = (1-nu1^2)/E1 + (1-nu2^2)/E2"});
  // Effects that would do nothing: refused rather than silently ignored.
  if (eff.finite_peclet && !eff.thermal)
    bad.Add({"", 0, "FilmEffects::finite_peclet", "true",
             "sets the surface temperatures of a thermal film; thermal is off",
             "thermal = true, or finite_peclet = false"});
  if (eff.roughness && !s1_ && !s2_)
    bad.Add({"", 0, "FilmEffects::roughness", "true", "both surfaces are null (smooth)",
             "a SurfaceShape for surface1 or surface2, or roughness = false"});
  bad.ThrowIfAny();
  const int n = grid.size();
  x2_.resize(n);
  for (int i = 0; i < n; ++i) x2_[i] = 0.5 * grid.x(i) * grid.x(i);
  if (eff.elastic) elastic_.emplace(n, grid.dx_m(), e_prime, opt.fft_plan_effort);
  if (eff.roughness) heights_.setZero(n);
  if (eff.thermal || eff.non_newtonian)
    field_ = std::make_unique<internal::FilmField>(grid, lub, eff, solids, opt);
  const bool small = n <= opt.dense_max_nodes;
  if (opt.linear_solver == LinearSolverKind::kDense) {
    linear_ = internal::MakeDenseLuSolver();
  } else if (opt.linear_solver == LinearSolverKind::kReusedLu ||
             (opt.linear_solver == LinearSolverKind::kAuto && small)) {
    internal::KrylovSettings k;
    k.restart = opt.gmres_restart;
    k.max_iterations = opt.reused_lu_max_gmres;
    linear_ = internal::MakeReusedLuSolver(k);
  } else {
    internal::KrylovSettings k;
    k.restart = opt.gmres_restart;
    k.max_iterations = opt.gmres_max_iterations;
    k.band = opt.preconditioner_band;
    k.coarse_pressures = opt.preconditioner_coarse_pressures;
    k.inlet_hats = opt.preconditioner_inlet_hats;
    k.outlet_refresh = opt.preconditioner_outlet_refresh;
    linear_ = internal::MakeNewtonKrylovSolver(k);
  }
}

FluidLaws LineContactSolver::Impl::Fluid(const ContactConditions& c, double pressure_scale) const {
  FluidLaws f;
  f.viscosity = &lub_.viscosity();
  f.density = &lub_.density();
  f.piezoviscous = eff_.piezoviscous;
  f.compressible = eff_.compressible;
  f.temperature_k = c.temperature_k;
  f.pressure_scale = pressure_scale;
  if (field_) {
    f.film_temperature_k = field_->temperature();
    f.viscosity_factor = field_->viscosity_factor();
    f.u1_m_s = c.u1_m_s;
    f.u2_m_s = c.u2_m_s;
  }
  return f;
}

void LineContactSolver::Impl::Film(const ContactConditions& c, FilmState* s) const {
  const int n = grid_.size();
  s->h_m.resize(n);
  if (elastic_) {
    elastic_->Apply(s->p_pa.data(), s->h_m.data());
  } else {
    s->h_m.setZero();
  }
  s->h_m.array() += s->h0_m + x2_.array() / c.reduced_radius_m;
  if (eff_.roughness) {
    // The surfaces move between time levels only: the Newton iterations of a step share one
    // (travel1, travel2), so the heights are sampled once per level (one sin per node and
    // surface: about 5 % of a rough cycle when sampled at every residual).
    if (!(s->travel1_m == heights_travel_m_[0] && s->travel2_m == heights_travel_m_[1])) {
      const std::vector<double> x = grid_.Nodes();
      heights_.setZero();
      Eigen::VectorXd tmp(n);
      for (const auto& [shape, travel] :
           {std::pair{s1_.get(), s->travel1_m}, std::pair{s2_.get(), s->travel2_m}}) {
        if (!shape) continue;
        SampleHeights(*shape, x.data(), n, travel, tmp.data());
        heights_ += tmp;
      }
      heights_travel_m_ = {s->travel1_m, s->travel2_m};
    }
    s->h_m -= heights_;
  }
}

LineContactSolver::Impl::Scales LineContactSolver::Impl::ScalesFor(
    const ContactConditions& c) const {
  const HertzScales hz = LineContactHertz(c.load_n_per_m, c.reduced_radius_m, e_prime_);
  Scales s;
  s.h_ref = std::max(EstimateCentralFilm(c), 1e-12);
  s.p_ref = eff_.elastic ? hz.max_pressure_pa
                         : c.load_n_per_m / std::sqrt(2.0 * c.reduced_radius_m * s.h_ref);
  return s;
}

double LineContactSolver::Impl::EstimateCentralFilm(const ContactConditions& c) const {
  const double eta0 = lub_.viscosity().Evaluate(0.0, c.temperature_k).eta_pa_s;
  const double alpha = eff_.piezoviscous ? lub_.viscosity().PressureViscosityCoefficient() : 0.0;
  return EstimatedCentralFilmM(eta0, alpha, c.um(), c.load_n_per_m, c.reduced_radius_m, e_prime_,
                               eff_.elastic);
}

FilmState LineContactSolver::Impl::InitialGuess(const ContactConditions& c,
                                                const FilmState* clock) const {
  const int n = grid_.size();
  FilmState s;
  if (clock) internal::CopyClock(*clock, &s);
  s.p_pa.setZero(n);
  const double h_c = EstimateCentralFilm(c);
  const HertzScales hz = LineContactHertz(c.load_n_per_m, c.reduced_radius_m, e_prime_);
  const double half =
      eff_.elastic ? hz.half_width_m : 2.0 * std::sqrt(2.0 * c.reduced_radius_m * h_c);
  for (int i = 1; i < n - 1; ++i) {
    const double xi = grid_.x(i) / half;
    if (std::abs(xi) < 1.0) s.p_pa[i] = std::sqrt(1.0 - xi * xi);
  }
  if (s.p_pa.sum() <= 0) s.p_pa.segment(1, n - 2).setConstant(1.0);  // grid finer than b
  s.p_pa *= c.load_n_per_m / (grid_.dx_m() * s.p_pa.sum());
  s.h0_m = 0.0;
  Film(c, &s);
  s.h0_m = h_c - s.CentralFilm(grid_);
  Film(c, &s);
  return s;
}

Eigen::VectorXd LineContactSolver::Impl::MassFlow(const ContactConditions& c, const FilmState& st) {
  if (field_) field_->Begin(c, st);
  FilmState s = st;
  Film(c, &s);
  sys_.Evaluate(Fluid(c), c.um(), s.p_pa, s.h_m, TimeDerivative{}, false);
  return sys_.MassFlow(c.um(), s.p_pa);
}

// ---------------------------------------------------------------------------------------
LineContactSolver::LineContactSolver(const UniformGrid& grid,
                                     double e_prime_pa,
                                     const Lubricant& lubricant,
                                     const FilmEffects& effects,
                                     const Options& options,
                                     std::shared_ptr<const SurfaceShape> surface1,
                                     std::shared_ptr<const SurfaceShape> surface2,
                                     const ContactSolids& solids)
    : impl_(std::make_unique<Impl>(grid,
                                   e_prime_pa,
                                   lubricant,
                                   effects,
                                   options,
                                   std::move(surface1),
                                   std::move(surface2),
                                   solids)) {}
LineContactSolver::~LineContactSolver() = default;
LineContactSolver::LineContactSolver(LineContactSolver&&) noexcept = default;
LineContactSolver& LineContactSolver::operator=(LineContactSolver&&) noexcept = default;
const UniformGrid& LineContactSolver::grid() const { return impl_->grid(); }
const LineContactSolver::Options& LineContactSolver::options() const { return impl_->options(); }
FilmState LineContactSolver::InitialGuess(const ContactConditions& c) const {
  return impl_->InitialGuess(c);
}
namespace {

// Why `s` cannot be the film of a solver on `grid` ("" when it can). An empty state is a film
// only where `empty_ok` (a cold steady solve).
std::string StateProblem(const UniformGrid& grid, const FilmState* s, bool empty_ok) {
  if (!s) return "the film state pointer is null";
  if (empty_ok && s->p_pa.size() == 0 && s->h_m.size() == 0) return "";
  const Eigen::Index n = grid.size();
  if (!s->valid() || s->p_pa.size() != n)
    return "the film state has " + std::to_string(s->p_pa.size()) + " pressures and " +
           std::to_string(s->h_m.size()) + " film thicknesses, this solver's grid " +
           std::to_string(n) + " nodes (" +
           (empty_ok ? "an empty state starts cold" : "solve it with SolveSteady first") + ")";
  const FilmTemperature& t = s->temperature;
  if (t.t_k.size() > 0 && t.t_k.rows() != n)
    return "the film temperature has " + std::to_string(t.t_k.rows()) + " rows, the grid " +
           std::to_string(n) + " nodes";
  return "";
}

// Summary::outlet_cut: a converged film still under pressure at the last inner node.
bool OutletCut(const LineContactSolver::Summary& sum, const FilmState& s) {
  const Eigen::Index n = s.p_pa.size();
  // Above round-off of the film's own pressure scale: a cavitated node holds exactly 0.
  return sum.usable() && n >= 3 && s.p_pa[n - 2] > 1e-9 * s.p_pa.maxCoeff();
}

LineContactSolver::Summary InvalidState(std::string why) {
  LineContactSolver::Summary sum;
  sum.termination = LineContactSolver::Termination::kInvalidInput;
  sum.message = "invalid film state: " + std::move(why);
  return sum;
}

}  // namespace

LineContactSolver::Summary LineContactSolver::SolveSteady(const ContactConditions& c,
                                                          FilmState* state) {
  if (std::string why = StateProblem(grid(), state, true); !why.empty())
    return InvalidState(std::move(why));
  if (state->solved_for) impl_->PredictHertzSimilar(*state->solved_for, c, state);
  Summary sum = impl_->SolveCoupled(c, internal::TimeDerivative{}, nullptr, 0.0, state);
  if (sum.usable()) state->solved_for = c;
  sum.outlet_cut = OutletCut(sum, *state);
  return sum;
}
void LineContactSolver::BeginTransient(const ContactConditions& c, const FilmState& initial) {
  if (std::string why = StateProblem(grid(), &initial, false); !why.empty())
    throw InputError(InputProblem{"", 0, "BeginTransient.initial", "",
                                  "is not a film of this solver: " + why,
                                  "a state solved on this solver's grid"});
  impl_->BeginTransient(c, initial);
}
LineContactSolver::Summary LineContactSolver::Step(const ContactConditions& c,
                                                   double dt,
                                                   FilmState* state,
                                                   const ContactConditions* c_start) {
  if (std::string why = StateProblem(grid(), state, false); !why.empty())
    return InvalidState(std::move(why));
  Summary sum = impl_->Step(c, dt, state, c_start);
  if (sum.usable()) state->solved_for = c;
  sum.outlet_cut = OutletCut(sum, *state);
  return sum;
}
double LineContactSolver::ResidualNorm(const ContactConditions& c, const FilmState& s) const {
  if (!StateProblem(grid(), &s, false).empty()) return std::numeric_limits<double>::quiet_NaN();
  return impl_->ResidualNorm(c, s);
}
Eigen::VectorXd LineContactSolver::MassFlow(const ContactConditions& c, const FilmState& s) const {
  if (!StateProblem(grid(), &s, false).empty()) return {};
  return impl_->MassFlow(c, s);
}
LineContactSolver::TransientHistory LineContactSolver::SaveTransient() const {
  return impl_->SaveTransient();
}
void LineContactSolver::RestoreTransient(const TransientHistory& h) { impl_->RestoreTransient(h); }
FilmFriction LineContactSolver::Friction(const ContactConditions& c, const FilmState& s) const {
  return impl_->Friction(c, s);
}

}  // namespace tehl

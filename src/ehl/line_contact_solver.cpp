#include "tehl/ehl/line_contact_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <sstream>

#include "base/schema.hpp"
#include "ehl/film_field.hpp"
#include "ehl/fixed_point_newton.hpp"
#include "ehl/newton_system.hpp"
#include "ehl/reynolds_system.hpp"
#include "tehl/ehl/elastic_deflection.hpp"
#include "tehl/ehl/film_thickness_formulas.hpp"
#include "tehl/ehl/surface_roughness.hpp"
#include "tehl/error.hpp"
#include "tehl/lubricant/lubricant.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {
using internal::FluidLaws;
using internal::NewtonSystem;
using internal::ReynoldsSystem;
using internal::TimeDerivative;
using Clock = std::chrono::steady_clock;
// Newton on the thermal coupling: each map evaluation's energy solve tolerance and the
// finite-difference step of its directional derivatives [K] (noise / step ~ 1e-4).
constexpr double kCouplingMapToleranceK = 1e-5;
constexpr double kCouplingFdStepK = 0.1;
constexpr double kCouplingMapPressureTolerance = 1e-11;  // [-]
// Coupled (thermal) grid sequencing stops at this many nodes [-].
constexpr int kMinThermalCoarseNodes = 65;
// Newton tolerance of the early thermal coupling iterations [-].
constexpr double kCouplingNewtonTolerance = 1e-5;
}  // namespace

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
  // The parabola through the smallest node and its neighbours: h_min between nodes.
  const double a = h_m[i - 1], b = h_m[i + 1], curv = a - 2 * hmin + b;
  return curv > 0 ? hmin - (b - a) * (b - a) / (8 * curv) : hmin;
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
                    internal::FormatReal(v) + " violates " + c);
  };
  rule(upwind_order == 1 || upwind_order == 2, "upwind_order", upwind_order, "1 or 2");
  rule(tolerance > 0 && tolerance < 1, "tolerance", tolerance, "in (0, 1)");
  rule(max_iterations >= 1, "max_iterations", max_iterations, ">= 1");
  rule(dense_max_nodes >= 5, "dense_max_nodes", dense_max_nodes, ">= 5");
  rule(gmres_restart >= 2, "gmres_restart", gmres_restart, ">= 2");
  rule(gmres_max_iterations >= 1, "gmres_max_iterations", gmres_max_iterations, ">= 1");
  rule(reused_lu_max_gmres >= 1, "reused_lu_max_gmres", reused_lu_max_gmres, ">= 1");
  rule(preconditioner_band >= 0, "preconditioner_band", preconditioner_band, ">= 0");
  rule(max_continuation_stages >= 0, "max_continuation_stages", max_continuation_stages, ">= 0");
  rule(min_step_fraction > 0 && min_step_fraction <= 1, "min_step_fraction", min_step_fraction,
       "in (0, 1]");
  rule(film_nodes >= 3, "film_nodes", film_nodes, ">= 3");
  rule(thermal_tolerance_k > 0, "thermal_tolerance_k", thermal_tolerance_k, "> 0");
  rule(coupling_pressure_tolerance > 0, "coupling_pressure_tolerance", coupling_pressure_tolerance,
       "> 0");
  rule(max_coupling_iterations >= 1, "max_coupling_iterations", max_coupling_iterations, ">= 1");
  rule(thermal_relaxation > 0 && thermal_relaxation <= 1, "thermal_relaxation", thermal_relaxation,
       "in (0, 1]");
  rule(coupling_newton_after >= 0, "coupling_newton_after", coupling_newton_after, ">= 0");
  return bad;
}

std::string LineContactSolver::Summary::BriefReport() const {
  std::ostringstream o;
  o << ToString(termination) << ": " << total_iterations << " Newton iterations";
  if (continuation_stages) o << " (" << continuation_stages << " continuation stages)";
  if (krylov_iterations) o << ", " << krylov_iterations << " GMRES iterations";
  if (substeps > 1) o << ", " << substeps << " substeps";
  if (coupling_iterations)
    o << ", " << coupling_iterations << " thermal coupling iterations (last dT "
      << temperature_change_k << " K, energy balance " << energy_balance_error << ")";
  if (coupling_newton_iterations)
    o << ", " << coupling_newton_iterations << " coupling Newton steps";
  o << ", residual " << residual << ", load error " << load_error << ", " << linear_solver << ", "
    << wall_time_s << " s";
  if (!usable()) o << ": " << message;
  return o.str();
}

// ---------------------------------------------------------------------------------------
class LineContactSolver::Impl {
 public:
  Impl(const UniformGrid& grid,
       double e_prime,
       const Lubricant& lub,
       const FilmEffects& eff,
       const Options& opt,
       std::shared_ptr<const SurfaceShape> s1,
       std::shared_ptr<const SurfaceShape> s2,
       const ContactSolids& solids)
      : grid_(grid),
        e_prime_(e_prime),
        lub_(lub),
        eff_(eff),
        opt_(opt),
        s1_(std::move(s1)),
        s2_(std::move(s2)),
        solids_(solids),
        sys_(grid.size(), grid.dx_m(), opt.upwind_order) {
    ProblemList bad;
    for (const auto& m : opt.Validate()) bad.Add({"", 0, "LineContactSolver::Options", "", m, ""});
    if (!(e_prime > 0))
      bad.Add({"", 0, "e_prime_pa", internal::FormatReal(e_prime), "must be > 0", "E' > 0 [Pa]"});
    bad.ThrowIfAny();
    const int n = grid.size();
    x2_.resize(n);
    for (int i = 0; i < n; ++i) x2_[i] = 0.5 * grid.x(i) * grid.x(i);
    if (eff.elastic) elastic_.emplace(n, grid.dx_m(), e_prime);
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
      linear_ = internal::MakeNewtonKrylovSolver(k);
    }
  }

  const UniformGrid& grid() const { return grid_; }
  const Options& options() const { return opt_; }

  FluidLaws Fluid(const ContactConditions& c, double pressure_scale = 1.0) const {
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

  // Film h = h0 + x^2/(2R) + v(p) - heights at the state's travel.
  void Film(const ContactConditions& c, FilmState* s) const {
    const int n = grid_.size();
    s->h_m.resize(n);
    if (elastic_) {
      elastic_->Apply(s->p_pa.data(), s->h_m.data());
    } else {
      s->h_m.setZero();
    }
    s->h_m.array() += s->h0_m + x2_.array() / c.reduced_radius_m;
    if (eff_.roughness) {
      const std::vector<double> x = grid_.Nodes();
      heights_.setZero();
      Eigen::VectorXd tmp(n);
      for (const auto& [shape, travel] :
           {std::pair{s1_.get(), s->travel1_m}, std::pair{s2_.get(), s->travel2_m}}) {
        if (!shape) continue;
        SampleHeights(*shape, x.data(), n, travel, tmp.data());
        heights_ += tmp;
      }
      s->h_m -= heights_;
    }
  }

  struct Scales {
    double p_ref, h_ref;
  };

  Scales ScalesFor(const ContactConditions& c) const {
    const HertzScales hz = LineContactHertz(c.load_n_per_m, c.reduced_radius_m, e_prime_);
    Scales s;
    s.h_ref = std::max(EstimateCentralFilm(c), 1e-12);
    s.p_ref = eff_.elastic ? hz.max_pressure_pa
                           : c.load_n_per_m / std::sqrt(2.0 * c.reduced_radius_m * s.h_ref);
    return s;
  }

  double EstimateCentralFilm(const ContactConditions& c) const {
    const double eta0 = lub_.viscosity().Evaluate(0.0, c.temperature_k).eta_pa_s;
    if (!eff_.elastic && !eff_.piezoviscous)
      return MartinRigidFilmM(eta0, c.um(), c.reduced_radius_m, c.load_n_per_m);
    const double alpha = eff_.piezoviscous ? lub_.viscosity().PressureViscosityCoefficient() : 0.0;
    const DimensionlessGroups g =
        LineContactGroups(eta0, alpha, c.um(), c.load_n_per_m, c.reduced_radius_m, e_prime_);
    return MoesCentralFilmM(g.U, g.G, g.W, c.reduced_radius_m);
  }

  FilmState InitialGuess(const ContactConditions& c) const {
    const int n = grid_.size();
    FilmState s;
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

  // Row weights c_i = -1/|dr_i/dP_i| at the current linearization: the complementarity
  // min(P_i, c_i r_i) then compares two quantities of the same size (a pressure change),
  // however much rho h^3/(12 eta) varies along the film. Negative because the cavitated
  // branch has -r >= 0: a divergent gap could carry more flow than arrives.
  void UpdateRowWeights(const Scales& sc) {
    const int n = grid_.size();
    row_weight_.setZero(n);
    NewtonSystem ns = SystemFor(sc, 1.0);
    double largest = 0.0;
    for (int i = 1; i < n - 1; ++i) {
      row_weight_[i] = std::abs(ns.Diagonal(i)) * sc.p_ref;
      largest = std::max(largest, row_weight_[i]);
    }
    for (int i = 1; i < n - 1; ++i)
      row_weight_[i] = -1.0 / std::max(row_weight_[i], 1e-300 + 1e-14 * largest);
  }

  NewtonSystem SystemFor(const Scales& sc, double load) const {
    NewtonSystem ns;
    ns.n = grid_.size();
    ns.dx = grid_.dx_m();
    ns.p_ref = sc.p_ref;
    ns.h_ref = sc.h_ref;
    ns.row_scale = &row_weight_;
    ns.load = load;
    ns.a = &sys_.dr_dp();
    ns.b = &sys_.dr_dh();
    ns.elastic = elastic_ ? &*elastic_ : nullptr;
    return ns;
  }

  // Scaled residual F(z) of a state; false if the film is not positive or not finite.
  // `linearize` also refreshes the derivatives and the row weights.
  bool Residual(const ContactConditions& c,
                const FluidLaws& fluid,
                const Scales& sc,
                const TimeDerivative& td,
                FilmState* s,
                Eigen::VectorXd* f,
                bool linearize) {
    Film(c, s);
    if (!s->h_m.allFinite() || s->h_m.minCoeff() <= 0.0) return false;
    sys_.Evaluate(fluid, c.um(), s->p_pa, s->h_m, td, linearize);
    if (linearize) UpdateRowWeights(sc);
    const int n = grid_.size(), m = n - 2;
    f->resize(m + 1);
    cavitated_.assign(n, 0);
    for (int i = 1; i <= m; ++i) {
      const double pi = s->p_pa[i] / sc.p_ref;
      const double ri = row_weight_[i] * sys_.residual()[i];
      cavitated_[i] = pi <= ri;
      (*f)[i - 1] = std::min(pi, ri);
    }
    (*f)[m] = (grid_.dx_m() * s->p_pa.sum() - c.load_n_per_m) / c.load_n_per_m;
    return f->allFinite();
  }

  Summary Newton(const ContactConditions& c,
                 double pressure_scale,
                 const TimeDerivative& td,
                 FilmState* s) {
    Summary sum;
    sum.linear_solver = linear_->Name();
    const FluidLaws fluid = Fluid(c, pressure_scale);
    const Scales sc = ScalesFor(c);
    const int n = grid_.size(), m = n - 2;
    Eigen::VectorXd f, f_trial, dz;
    if (!Residual(c, fluid, sc, td, s, &f, true)) {
      // A non-positive film from the guess: lift h0 until the film is positive.
      const double lift = std::max(0.0, -s->h_m.minCoeff()) + sc.h_ref;
      s->h0_m += lift;
      if (!Residual(c, fluid, sc, td, s, &f, true)) {
        sum.termination = Termination::kInvalidInput;
        sum.message = "the initial guess gives a non-positive or non-finite film";
        return sum;
      }
    }
    NewtonSystem ns = SystemFor(sc, c.load_n_per_m);
    FilmState trial = *s;
    double norm = f.lpNorm<Eigen::Infinity>();
    sum.residual = norm;
    // Watchdog globalization (Chamberlain, Powell, Lemarechal & Pedersen 1982): a full Newton
    // step may raise ||F|| for a few iterations while the pressure spike and the cavitation
    // boundary move. Up to kWatchdog full steps are taken from a checkpoint; if ||F|| has not
    // fallen below the checkpoint's by then, the iteration returns there and backtracks.
    constexpr int kWatchdog = 3;
    int watchdog = 0;
    bool watchdog_allowed = true;
    FilmState checkpoint;
    Eigen::VectorXd f_check, dz_check;
    double phi_check = 0.0;
    auto try_step = [&](double lambda, const Eigen::VectorXd& dir, const FilmState& from) {
      // Projected step: p >= 0 holds at the solution, so negative pressures from a step
      // that moves the cavitation boundary are set to zero at once (without this the
      // boundary creeps one node per damped iteration on fine grids).
      trial.p_pa = from.p_pa;
      trial.p_pa.segment(1, m) += lambda * sc.p_ref * dir.head(m);
      trial.p_pa = trial.p_pa.cwiseMax(0.0);
      trial.h0_m = from.h0_m + lambda * sc.h_ref * dir[m];
      trial.travel1_m = from.travel1_m;
      trial.travel2_m = from.travel2_m;
      return Residual(c, fluid, sc, td, &trial, &f_trial, false);
    };
    for (int it = 0; it < opt_.max_iterations; ++it) {
      if (norm < opt_.tolerance) break;
      ns.cavitated = cavitated_;
      std::string why;
      if (!linear_->Solve(ns, -f, &dz, &why)) {
        sum.termination = Termination::kLinearSolverFailed;
        sum.message = why;
        return Finish(c, s, sum);
      }
      sum.krylov_iterations += linear_->last_krylov_iterations();
      double phi0 = f.norm();
      double lambda = 1.0;
      bool accepted = false;
      const bool full_ok = try_step(1.0, dz, *s);
      const double phi_full = full_ok ? f_trial.norm() : 0.0;
      if (full_ok && phi_full <= (1.0 - 1e-4) * phi0) {
        accepted = true;
      } else if (full_ok && watchdog_allowed && watchdog < kWatchdog) {
        if (watchdog == 0) {
          checkpoint = *s;
          f_check = f;
          dz_check = dz;
          phi_check = phi0;
        }
        ++watchdog;
        accepted = true;
      } else {
        if (watchdog > 0) {  // back to the checkpoint, then backtrack along its direction
          *s = checkpoint;
          Residual(c, fluid, sc, td, s, &f, true);
          dz = dz_check;
          phi0 = phi_check;
          watchdog = 0;
          watchdog_allowed = false;
        }
        for (lambda = 0.5; lambda >= opt_.min_step_fraction; lambda *= 0.5) {
          if (try_step(lambda, dz, *s) && f_trial.norm() <= (1.0 - 1e-4 * lambda) * phi0) {
            accepted = true;
            break;
          }
        }
      }
      if (!accepted) {
        sum.iterations = it;
        sum.termination = Termination::kLineSearchFailed;
        sum.message = "line search found no decrease of the residual (step " +
                      internal::FormatReal(lambda) + ") at residual " + internal::FormatReal(norm);
        Residual(c, fluid, sc, td, s, &f, false);
        return Finish(c, s, sum);
      }
      std::swap(s->p_pa, trial.p_pa);
      s->h0_m = trial.h0_m;
      Residual(c, fluid, sc, td, s, &f, true);
      norm = f.lpNorm<Eigen::Infinity>();
      if (watchdog > 0 && f.norm() <= (1.0 - 1e-4) * phi_check) {
        watchdog = 0;  // the full steps paid off
        watchdog_allowed = true;
      } else if (watchdog == 0 && lambda < 1.0) {
        watchdog_allowed = true;  // a damped step was taken: full steps may be tried again
      }
      IterationRecord rec;
      rec.residual = norm;
      rec.step = lambda;
      rec.krylov_iterations = linear_->last_krylov_iterations();
      rec.cavitated_nodes = static_cast<int>(std::count(cavitated_.begin(), cavitated_.end(), 1));
      sum.history.push_back(rec);
      sum.iterations = it + 1;
    }
    sum.residual = norm;
    if (norm < opt_.tolerance) {
      sum.termination = Termination::kConverged;
      sum.message = "converged";
    } else {
      sum.termination = Termination::kMaxIterations;
      sum.message = "no convergence in " + std::to_string(opt_.max_iterations) +
                    " Newton iterations (residual " + internal::FormatReal(norm) + ")";
    }
    return Finish(c, s, sum);
  }

  Summary Finish(const ContactConditions& c, FilmState* s, Summary sum) {
    // The reported pressure is the complementarity solution: p >= 0 exactly.
    s->p_pa = s->p_pa.cwiseMax(0.0);
    Film(c, s);
    sum.total_iterations = sum.iterations;
    sum.load_error = std::abs(grid_.dx_m() * s->p_pa.sum() - c.load_n_per_m) / c.load_n_per_m;
    return sum;
  }

  bool ValidConditions(const ContactConditions& c, Summary* sum) const {
    std::string bad;
    if (!(c.reduced_radius_m > 0) || !std::isfinite(c.reduced_radius_m)) bad += " R <= 0;";
    if (!(c.load_n_per_m > 0) || !std::isfinite(c.load_n_per_m)) bad += " w <= 0;";
    if (!(c.um() > 0) || !std::isfinite(c.um()))
      bad += " entrainment speed um <= 0 (the inlet is at x_start);";
    if (!(c.temperature_k > 0)) bad += " T <= 0 K;";
    if (bad.empty()) return true;
    sum->termination = Termination::kInvalidInput;
    sum->message = "invalid contact conditions:" + bad;
    return false;
  }

  // Newton, then continuation in load and pressure-viscosity coefficient if it fails.
  Summary Solve(const ContactConditions& c, const TimeDerivative& td, FilmState* s) {
    const auto t0 = Clock::now();
    Summary sum;
    if (!ValidConditions(c, &sum)) return sum;
    if (!s->valid() || s->p_pa.size() != grid_.size()) *s = SequencedGuess(c, td);
    const FilmState start = *s;
    sum = Newton(c, 1.0, td, s);
    int total = sum.total_iterations, krylov = sum.krylov_iterations, stages = 0;
    if (!sum.usable() && opt_.max_continuation_stages > 0 && !td.active) {
      // Continuation: theta scales the load and the pressure-viscosity coefficient.
      const std::string first_failure = sum.message;
      *s = InitialGuess(ContactConditions{c.reduced_radius_m, c.u1_m_s, c.u2_m_s,
                                          0.05 * c.load_n_per_m, c.temperature_k});
      double theta = 0.05, growth = 2.0;
      Summary stage;
      while (stages < opt_.max_continuation_stages) {
        ContactConditions ci = c;
        ci.load_n_per_m = theta * c.load_n_per_m;
        FilmState trial = *s;
        stage = Newton(ci, theta, td, &trial);
        ++stages;
        total += stage.total_iterations;
        krylov += stage.krylov_iterations;
        if (stage.usable()) {
          *s = trial;
          if (theta >= 1.0) break;
          theta = std::min(1.0, theta * growth);
        } else {
          growth = std::sqrt(growth);
          theta = theta / std::sqrt(growth);
          if (growth < 1.01) break;
        }
      }
      sum = stage;
      if (!sum.usable()) {
        sum.message = "no convergence directly (" + first_failure +
                      ") nor by continuation in "
                      "load and pressure-viscosity coefficient (" +
                      stage.message + ")";
        if (!s->valid()) *s = start;
      }
    }
    sum.total_iterations = total;
    sum.krylov_iterations = krylov;
    sum.continuation_stages = stages;
    sum.wall_time_s = std::chrono::duration<double>(Clock::now() - t0).count();
    return sum;
  }

  // Grid sequencing: without a usable guess, solve on a grid with half the cells (down to
  // opt_.coarse_grid_nodes) and interpolate. A damped Newton method moves the cavitation
  // boundary about one node per iteration, so the fine grid should start next to it.
  FilmState SequencedGuess(const ContactConditions& c, const TimeDerivative& td) {
    const int n = grid_.size();
    const int nc = (n - 1) / 2 + 1;
    if (td.active || nc < opt_.coarse_grid_nodes) return InitialGuess(c);
    if (!coarse_) {
      Options o = opt_;
      o.linear_solver = LinearSolverKind::kAuto;
      // The coarse guess is isothermal and Newtonian: the fine grid couples the fields.
      FilmEffects coarse_effects = eff_;
      coarse_effects.thermal = false;
      coarse_effects.non_newtonian = false;
      coarse_ = std::make_unique<Impl>(UniformGrid(grid_.x_start_m(), grid_.x_end_m(), nc),
                                       e_prime_, lub_, coarse_effects, o, s1_, s2_, solids_);
    }
    FilmState cs;
    cs.time_s = 0;
    const Summary sum = coarse_->Solve(c, TimeDerivative{}, &cs);
    if (!sum.usable()) return InitialGuess(c);
    return Interpolated(coarse_->grid_, cs, c);
  }

  // --- transient ----------------------------------------------------------------------
  struct History {
    int levels = 0;            // stored levels (1 or 2)
    Eigen::VectorXd q1, q2;    // rho h at t_{n-1}, t_{n-2}
    double dt_prev = 0;        // t_{n-1} - t_{n-2}
    ContactConditions c_prev;  // conditions at t_{n-1}
    Eigen::MatrixXd t_prev;    // film temperature at t_{n-2} (thermal; empty before) [K]
  };

  Eigen::VectorXd RhoH(const ContactConditions& c, FilmState s) {
    Film(c, &s);
    TimeDerivative none;
    sys_.Evaluate(Fluid(c), c.um(), s.p_pa, s.h_m, none, false);
    return sys_.rho_h();
  }

  void BeginTransient(const ContactConditions& c, const FilmState& s) {
    if (field_) field_->Begin(c, s);
    hist_ = History{};
    hist_.levels = 1;
    hist_.q1 = RhoH(c, s);
    hist_.c_prev = c;
  }

  TimeDerivative Derivative(double dt) const {
    TimeDerivative td;
    if (!eff_.transient || hist_.levels == 0) return td;
    td.active = true;
    td.q1 = hist_.q1;
    if (hist_.levels >= 2 && opt_.time_scheme == TimeScheme::kBdf2) {
      // Variable-step BDF2 (omega = dt_n / dt_{n-1}).
      const double w = dt / hist_.dt_prev;
      td.a0 = (1 + 2 * w) / ((1 + w) * dt);
      td.a1 = -(1 + w) / dt;
      td.a2 = w * w / ((1 + w) * dt);
      td.q2 = hist_.q2;
    } else {
      td.a0 = 1.0 / dt;
      td.a1 = -1.0 / dt;
      td.a2 = 0.0;
      td.q2 = hist_.q1;
    }
    return td;
  }

  Summary OneStep(const ContactConditions& c, double dt, FilmState* s) {
    FilmState next = *s;
    next.time_s = s->time_s + dt;
    next.travel1_m = s->travel1_m + 0.5 * dt * (hist_.c_prev.u1_m_s + c.u1_m_s);
    next.travel2_m = s->travel2_m + 0.5 * dt * (hist_.c_prev.u2_m_s + c.u2_m_s);
    const TimeDerivative td = Derivative(dt);
    ExtrapolateTemperature(dt, *s, &next);
    Summary sum = SolveCoupled(c, td, s, eff_.transient ? dt : 0.0, &next);
    if (sum.usable()) {
      if (eff_.thermal) hist_.t_prev = s->temperature.t_k;
      *s = next;
      hist_.q2 = hist_.q1;
      hist_.q1 = RhoH(c, next);
      hist_.levels = std::min(hist_.levels + 1, 2);
      hist_.dt_prev = dt;
      hist_.c_prev = c;
    }
    return sum;
  }

  // The coupling's starting temperature for a step: linear in time through the last two
  // levels (the energy equation's old level stays the state's). Measured on the thermal
  // seed 004 cycle: fewer coupling iterations per step than starting from the last level.
  void ExtrapolateTemperature(double dt, const FilmState& s, FilmState* next) const {
    const Eigen::MatrixXd& t_n = s.temperature.t_k;
    if (!eff_.thermal || hist_.dt_prev <= 0 || hist_.t_prev.size() == 0 ||
        hist_.t_prev.rows() != t_n.rows() || hist_.t_prev.cols() != t_n.cols())
      return;
    const double t0 = hist_.c_prev.temperature_k;
    FilmTemperature& t = next->temperature;
    t.t_k = (t_n + (dt / hist_.dt_prev) * (t_n - hist_.t_prev)).cwiseMax(0.8 * t0);
    t.t1_k = t.t_k.col(0);
    t.t2_k = t.t_k.col(t.t_k.cols() - 1);
  }

  Summary Step(const ContactConditions& c_new, double dt, FilmState* s) {
    const auto t0 = Clock::now();
    Summary sum;
    if (!(dt > 0) || !std::isfinite(dt)) {
      sum.message = "time step must be > 0";
      return sum;
    }
    if (hist_.levels == 0) BeginTransient(c_new, *s);
    const History saved_hist = hist_;
    const FilmState saved_state = *s;
    int total = 0, krylov = 0;
    for (int parts : {1, 2, 4}) {
      hist_ = saved_hist;
      *s = saved_state;
      const ContactConditions c_old = hist_.c_prev;
      bool ok = true;
      for (int k = 1; k <= parts && ok; ++k) {
        const double f = static_cast<double>(k) / parts;
        ContactConditions ck = c_new;
        ck.reduced_radius_m =
            c_old.reduced_radius_m + f * (c_new.reduced_radius_m - c_old.reduced_radius_m);
        ck.u1_m_s = c_old.u1_m_s + f * (c_new.u1_m_s - c_old.u1_m_s);
        ck.u2_m_s = c_old.u2_m_s + f * (c_new.u2_m_s - c_old.u2_m_s);
        ck.load_n_per_m = c_old.load_n_per_m + f * (c_new.load_n_per_m - c_old.load_n_per_m);
        ck.temperature_k = c_old.temperature_k + f * (c_new.temperature_k - c_old.temperature_k);
        sum = OneStep(ck, dt / parts, s);
        total += sum.total_iterations;
        krylov += sum.krylov_iterations;
        ok = sum.usable();
      }
      sum.substeps = parts;
      if (ok) break;
    }
    if (!sum.usable()) {
      hist_ = saved_hist;
      // Keep the best iterate of the last attempt (finite by construction).
    }
    sum.total_iterations = total;
    sum.krylov_iterations = krylov;
    sum.wall_time_s = std::chrono::duration<double>(Clock::now() - t0).count();
    return sum;
  }

  double ResidualNorm(const ContactConditions& c, const FilmState& st) {
    if (field_) field_->Begin(c, st);
    FilmState s = st;
    Eigen::VectorXd f;
    if (!Residual(c, Fluid(c), ScalesFor(c), TimeDerivative{}, &s, &f, true))
      return std::numeric_limits<double>::infinity();
    return f.lpNorm<Eigen::Infinity>();
  }

  Eigen::VectorXd MassFlow(const ContactConditions& c, const FilmState& st) {
    if (field_) field_->Begin(c, st);
    FilmState s = st;
    Film(c, &s);
    sys_.Evaluate(Fluid(c), c.um(), s.p_pa, s.h_m, TimeDerivative{}, false);
    return sys_.MassFlow(c.um(), s.p_pa);
  }

  TransientHistory SaveTransient() const {
    return TransientHistory{hist_.levels,  hist_.q1,     hist_.q2,
                            hist_.dt_prev, hist_.c_prev, hist_.t_prev};
  }
  void RestoreTransient(const TransientHistory& h) {
    hist_.levels = h.levels;
    hist_.q1 = h.q1;
    hist_.q2 = h.q2;
    hist_.dt_prev = h.dt_prev_s;
    hist_.c_prev = h.c_prev;
    hist_.t_prev = h.t_prev_k;
  }

  FilmFriction Friction(const ContactConditions& c, const FilmState& st) {
    FilmState s = st;
    Film(c, &s);
    if (field_) {
      field_->Begin(c, st);
      return field_->Friction(c, s);
    }
    // Newtonian, isothermal: eta(p, T0) uniform across the film (two cross-film nodes).
    return internal::IntegrateFriction(grid_, s, c, 2, [&](int i, double* eta) {
      const double p = eff_.piezoviscous ? std::max(s.p_pa[i], 0.0) : 0.0;
      eta[0] = eta[1] = lub_.viscosity().Evaluate(p, c.temperature_k).eta_pa_s;
    });
  }

  struct CouplingNewton {
    internal::FixedPointNewtonResult result;
    Summary pressure;     // the last pressure solve (at the returned temperature)
    double balance = -1;  // energy balance error of the last energy solve [-]
  };
  // Newton-Krylov on T = G(T), G = the energy solve at the pressure solved with the film at T
  // (ehl/fixed_point_newton.hpp), from the field's temperature and the state *s; on return
  // *s holds the pressure solved at the last temperature, which the field holds.
  CouplingNewton NewtonCoupling(const ContactConditions& c,
                                const TimeDerivative& td,
                                const FilmState* previous,
                                double dt_s,
                                FilmState* s) {
    CouplingNewton out;
    const Eigen::MatrixXd start = field_->film_temperature();
    const Eigen::Index rows = start.rows(), cols = start.cols();
    FilmState work = *s;
    Eigen::MatrixXd image;
    const internal::FixedPointMap map = [&](const Eigen::VectorXd& x, Eigen::VectorXd* g) {
      field_->SetTemperature(Eigen::Map<const Eigen::MatrixXd>(x.data(), rows, cols));
      FilmState trial = work;
      const double keep_tolerance = opt_.tolerance;
      opt_.tolerance = std::min(opt_.tolerance, kCouplingMapPressureTolerance);
      out.pressure = Solve(c, td, &trial);
      opt_.tolerance = keep_tolerance;
      if (!out.pressure.usable()) return false;
      internal::FilmField::EnergyUpdate e;
      try {
        e = field_->MapTemperature(c, trial, previous, dt_s, kCouplingMapToleranceK, &image);
      } catch (const std::exception&) {
        return false;
      }
      if (!e.ok) return false;
      out.balance = e.summary.balance.RelativeError();
      work = trial;
      *g = Eigen::Map<const Eigen::VectorXd>(image.data(), image.size());
      return true;
    };
    internal::FixedPointNewtonOptions o;
    o.tolerance = opt_.thermal_tolerance_k;
    o.fd_step = kCouplingFdStepK;
    o.lower = internal::FilmField::MinTemperature(c.temperature_k);
    o.upper = internal::FilmField::MaxTemperature(c.temperature_k);
    Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(start.data(), start.size());
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

  // Thermal / non-Newtonian: pressure solves and field updates alternate until the fields
  // settle (DESIGN.md section 5); otherwise a plain pressure solve. `previous` and dt_s give
  // the energy equation its old level (dt_s <= 0: steady).
  //
  // A steady thermal solve whose coupling does not settle is sequenced like the pressure
  // (docs/theory.md, "Thermal coupling"): the coupled problem is solved on the grid of half
  // the cells (recursively, down to kMinThermalCoarseNodes), and the fine coupling starts from
  // its pressure and temperature. A sliding Newtonian film can have a cool and a hot branch
  // of steady solutions (the cool one ends in a fold as the slide grows); the coarse grid
  // lands on the hot branch where the fine iteration, started cold, cannot.
  Summary SolveCoupled(const ContactConditions& c,
                       const TimeDerivative& td,
                       const FilmState* previous,
                       double dt_s,
                       FilmState* s) {
    const bool steady = dt_s <= 0 && !td.active;
    const int nc = (grid_.size() - 1) / 2 + 1;
    const bool sequence = eff_.thermal && steady && nc >= kMinThermalCoarseNodes;
    // Where a coarse grid can start it, the fine Newton waits for that start: from the
    // stalled alternation it rarely converges (measured on the sliding discs).
    Summary sum = CoupleOnce(c, td, previous, dt_s, !sequence, s);
    if (sum.usable() || !sequence || sum.termination != Termination::kCouplingNotConverged)
      return sum;
    const auto t0 = Clock::now();
    if (!thermal_coarse_)
      thermal_coarse_ = std::make_unique<Impl>(UniformGrid(grid_.x_start_m(), grid_.x_end_m(), nc),
                                               e_prime_, lub_, eff_, opt_, s1_, s2_, solids_);
    FilmState cs;
    const Summary coarse = thermal_coarse_->SolveCoupled(c, td, nullptr, 0.0, &cs);
    Summary total = sum;
    total.total_iterations += coarse.total_iterations;
    total.krylov_iterations += coarse.krylov_iterations;
    total.coupling_iterations += coarse.coupling_iterations;
    total.coupling_newton_iterations += coarse.coupling_newton_iterations;
    if (coarse.usable()) {
      FilmState fine = Interpolated(thermal_coarse_->grid_, cs, c);
      const Summary again = CoupleOnce(c, td, previous, dt_s, true, &fine);
      total.total_iterations += again.total_iterations;
      total.krylov_iterations += again.krylov_iterations;
      total.coupling_iterations += again.coupling_iterations;
      total.coupling_newton_iterations += again.coupling_newton_iterations;
      if (std::getenv("TEHL_DEBUG_COUPLING"))
        std::fprintf(stderr, "thermal sequencing %d -> %d: %s\n", nc, grid_.size(),
                     again.usable() ? "settled" : again.message.c_str());
      if (again.usable()) {
        *s = fine;
        Summary done = again;
        done.total_iterations = total.total_iterations;
        done.krylov_iterations = total.krylov_iterations;
        done.coupling_iterations = total.coupling_iterations;
        done.coupling_newton_iterations = total.coupling_newton_iterations;
        done.wall_time_s = sum.wall_time_s + std::chrono::duration<double>(Clock::now() - t0).count();
        return done;
      }
    }
    total.message += coarse.usable()
                         ? "; started from the coupled solution on " + std::to_string(nc) +
                               " nodes, it did not settle either"
                         : "; on " + std::to_string(nc) + " nodes it did not settle either";
    total.wall_time_s += std::chrono::duration<double>(Clock::now() - t0).count();
    return total;
  }

  // A state of grid g interpolated linearly onto this grid: pressure, rigid approach and (when
  // present) the film temperature, node row by node row.
  FilmState Interpolated(const UniformGrid& g, const FilmState& cs, const ContactConditions& c) {
    const int n = grid_.size();
    FilmState s;
    s.p_pa.setZero(n);
    const bool thermal = cs.temperature.t_k.rows() == g.size();
    if (thermal) s.temperature.t_k.resize(n, cs.temperature.t_k.cols());
    for (int i = 0; i < n; ++i) {
      const double t = (grid_.x(i) - g.x_start_m()) / g.dx_m();
      const int k = std::clamp(static_cast<int>(t), 0, g.size() - 2);
      const double f = std::clamp(t - k, 0.0, 1.0);
      if (i > 0 && i < n - 1) s.p_pa[i] = (1 - f) * cs.p_pa[k] + f * cs.p_pa[k + 1];
      if (thermal)
        s.temperature.t_k.row(i) =
            (1 - f) * cs.temperature.t_k.row(k) + f * cs.temperature.t_k.row(k + 1);
    }
    if (thermal) {
      const Eigen::Index nz = s.temperature.t_k.cols();
      s.temperature.t1_k = s.temperature.t_k.col(0);
      s.temperature.t2_k = s.temperature.t_k.col(nz - 1);
      s.temperature.q1_w_m2.setZero(n);
      s.temperature.q2_w_m2.setZero(n);
    }
    s.h0_m = cs.h0_m;
    Film(c, &s);
    return s;
  }

  // One coupled solve from *s: the alternation, then (newton: when it stalls) Newton on the
  // coupling.
  Summary CoupleOnce(const ContactConditions& c,
                     const TimeDerivative& td,
                     const FilmState* previous,
                     double dt_s,
                     bool newton,
                     FilmState* s) {
    if (!field_) return Solve(c, td, s);
    const auto t0 = Clock::now();
    field_->Begin(c, *s);
    Summary sum;
    int total = 0, krylov = 0, stages = 0, coupling = 0;
    double change_t = -1, change_f = 0, change_p = 1, balance = -1;
    Eigen::VectorXd p_last;
    bool settled = false;
    std::string energy_failure, newton_message;
    const double newton_tolerance = opt_.tolerance;
    // Newton on the coupling (Newtonian thermal runs) takes over from the best iterate when
    // the alternation stalls: no new smallest temperature change for coupling_newton_after
    // iterations, or all iterations used.
    const bool newton_possible =
        newton && eff_.thermal && !eff_.non_newtonian && opt_.coupling_newton_after > 0;
    double best_change = std::numeric_limits<double>::infinity();
    int since_best = 0;
    Eigen::MatrixXd best_t;
    FilmState best_s;
    for (int k = 0; k < opt_.max_coupling_iterations && !settled; ++k) {
      // Inexact coupling: while the temperature still moves by more than 10x its tolerance,
      // the pressure need not be solved to the final tolerance.
      opt_.tolerance = change_t > 10 * opt_.thermal_tolerance_k
                           ? std::max(newton_tolerance, kCouplingNewtonTolerance)
                           : newton_tolerance;
      sum = Solve(c, td, s);
      opt_.tolerance = newton_tolerance;
      total += sum.total_iterations;
      krylov += sum.krylov_iterations;
      stages += sum.continuation_stages;
      if (!sum.usable()) break;
      ++coupling;
      // Pressure change between coupling iterations, relative to p_max.
      if (p_last.size() == s->p_pa.size())
        change_p = (s->p_pa - p_last).cwiseAbs().maxCoeff() / std::max(s->MaxPressure(), 1.0);
      p_last = s->p_pa;
      change_f = field_->UpdateRheology(c, *s);
      change_t = 0.0;
      if (eff_.thermal) {
        // The energy solver checks its inputs and throws on a malformed flow field; inside a
        // coupling that can only come from a diverging iterate, which is a failed solve, not
        // bad input.
        internal::FilmField::EnergyUpdate e;
        const Eigen::MatrixXd t_in = field_->film_temperature();
        try {
          e = field_->UpdateTemperature(c, *s, previous, dt_s, opt_.thermal_relaxation);
        } catch (const std::exception& ex) {
          e.ok = false;
          e.summary.message = ex.what();
        }
        balance = e.summary.balance.RelativeError();
        change_t = e.max_change_k;
        if (newton_possible && e.ok && !e.limited) {
          if (change_t < best_change) {
            best_change = change_t;
            best_t = t_in;
            best_s = *s;
            since_best = 0;
          } else if (++since_best >= opt_.coupling_newton_after) {
            break;
          }
        }
        if (!e.ok) {
          energy_failure = e.summary.message;
          break;
        }
      }
      if (std::getenv("TEHL_DEBUG_COUPLING"))
        std::fprintf(stderr, "coupling %d: newton %d dT %g df %g dp %g balance %g\n", k,
                     sum.total_iterations, change_t, change_f, change_p, balance);
      // Thermal: the temperature settles. Non-Newtonian: the pressure settles (the Eyring factor
      // itself is spiky where dp/dx is large, so its own change is not the measure).
      settled = change_t < opt_.thermal_tolerance_k &&
                (!eff_.non_newtonian || change_p < opt_.coupling_pressure_tolerance);
      if (settled) {  // the pressure of the settled fields
        sum = Solve(c, td, s);
        total += sum.total_iterations;
        krylov += sum.krylov_iterations;
      }
    }
    if (!settled && newton_possible && best_t.size() > 0) {
      *s = best_s;
      field_->SetTemperature(best_t);
      const CouplingNewton nt = NewtonCoupling(c, td, previous, dt_s, s);
      total += nt.pressure.total_iterations;
      krylov += nt.pressure.krylov_iterations;
      coupling += nt.result.map_evaluations;
      change_t = nt.result.residual;
      balance = nt.balance;
      settled = nt.result.converged && nt.pressure.usable();
      sum = nt.pressure;  // the pressure solve at the returned temperature
      sum.coupling_newton_iterations = nt.result.newton_iterations;
      energy_failure.clear();
      newton_message = nt.result.message;
    }
    field_->Store(s);
    if (sum.usable() && !settled) {
      sum.termination = Termination::kCouplingNotConverged;
      sum.message = !energy_failure.empty()
                        ? "energy equation: " + energy_failure
                        : "the pressure/temperature coupling did not settle in " +
                              std::to_string(opt_.max_coupling_iterations) +
                              " iterations (last temperature change " +
                              internal::FormatReal(change_t) + " K, pressure change " +
                              internal::FormatReal(change_p) +
                              " p_max, largest log change "
                              "of the Eyring factor " +
                              internal::FormatReal(change_f) + ")" +
                              (newton_message.empty() ? ""
                                                      : "; Newton on the coupling: " +
                                                            newton_message);
    }
    sum.total_iterations = total;
    sum.krylov_iterations = krylov;
    sum.continuation_stages = stages;
    sum.coupling_iterations = coupling;
    sum.temperature_change_k = change_t;
    sum.energy_balance_error = balance;
    sum.wall_time_s = std::chrono::duration<double>(Clock::now() - t0).count();
    return sum;
  }

 private:
  UniformGrid grid_;
  double e_prime_;
  const Lubricant& lub_;
  FilmEffects eff_;
  Options opt_;
  std::shared_ptr<const SurfaceShape> s1_, s2_;
  ContactSolids solids_;
  ReynoldsSystem sys_;
  std::optional<ElasticDeflection> elastic_;
  std::unique_ptr<internal::NewtonLinearSolver> linear_;
  Eigen::VectorXd x2_, row_weight_;
  mutable Eigen::VectorXd heights_;
  std::vector<char> cavitated_;
  History hist_;
  std::unique_ptr<Impl> coarse_;                // grid sequencing, built on first use
  std::unique_ptr<Impl> thermal_coarse_;        // coupled grid sequencing, built on first use
  std::unique_ptr<internal::FilmField> field_;  // thermal / non-Newtonian runs only
};

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
LineContactSolver::Summary LineContactSolver::SolveSteady(const ContactConditions& c,
                                                          FilmState* state) {
  return impl_->SolveCoupled(c, internal::TimeDerivative{}, nullptr, 0.0, state);
}
void LineContactSolver::BeginTransient(const ContactConditions& c, const FilmState& initial) {
  impl_->BeginTransient(c, initial);
}
LineContactSolver::Summary LineContactSolver::Step(const ContactConditions& c,
                                                   double dt,
                                                   FilmState* state) {
  return impl_->Step(c, dt, state);
}
double LineContactSolver::ResidualNorm(const ContactConditions& c, const FilmState& s) const {
  return impl_->ResidualNorm(c, s);
}
Eigen::VectorXd LineContactSolver::MassFlow(const ContactConditions& c, const FilmState& s) const {
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

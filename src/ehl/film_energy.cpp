// Film energy equation with moving-solid surface temperatures: input checks, Picard loop and
// reports (include/tehl/ehl/film_energy.hpp). The discretization is in film_energy_system.cpp.
#include "tehl/ehl/film_energy.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "base/number_text.hpp"
#include "ehl/film_energy_system.hpp"
#include "ehl/solid_heat_history.hpp"
#include "tehl/error.hpp"
#include "tehl/lubricant/lubricant.hpp"

namespace tehl {

std::string ToString(FilmEnergySolver::Termination t) {
  switch (t) {
    case FilmEnergySolver::Termination::kConverged:
      return "converged";
    case FilmEnergySolver::Termination::kMaxIterations:
      return "max_iterations";
    case FilmEnergySolver::Termination::kLinearSolverFailed:
      return "linear_solver_failed";
  }
  return "unknown";
}

std::string ToString(FilmEnergySolver::Walls w) {
  return w == FilmEnergySolver::Walls::kMovingSolids ? "moving_solids" : "fixed_temperature";
}

double FilmTemperature::MaxTemperature() const { return t_k.size() ? t_k.maxCoeff() : 0.0; }

double FilmTemperature::MeanTemperature(int i) const {
  const int nz = static_cast<int>(t_k.cols());
  return (t_k.row(i).sum() - 0.5 * (t_k(i, 0) + t_k(i, nz - 1))) / (nz - 1);
}

bool FilmTemperature::Matches(int n, int nz) const {
  for (const SolidFluxLevel& l : earlier)
    if (l.q1_w_m2.size() != n || l.q2_w_m2.size() != n) return false;
  return t_k.rows() == n && t_k.cols() == nz && t1_k.size() == n && t2_k.size() == n &&
         q1_w_m2.size() == n && q2_w_m2.size() == n;
}

double EnergyBalance::RelativeError() const {
  const double generated = shear_w_m + compression_w_m;
  const double rest = convected_out_w_m + into_solid1_w_m + into_solid2_w_m + stored_w_m;
  return std::abs(generated - rest) / std::max(std::abs(generated), 1e-300);
}

std::string FilmEnergySolver::Summary::BriefReport() const {
  std::ostringstream s;
  s << "energy: " << ToString(termination) << " after " << iterations << " iterations, max change "
    << max_change_k << " K, balance error " << balance.RelativeError() << ", mass defect "
    << mass_defect << ", " << wall_time_s * 1e3 << " ms";
  if (krylov_iterations > 0) s << ", " << krylov_iterations << " GMRES iterations";
  if (!usable()) s << " (" << message << ")";
  return s.str();
}

std::vector<std::string> FilmEnergySolver::Options::Validate() const {
  std::vector<std::string> bad;
  auto rule = [&](bool ok, const char* field, double v, const char* c) {
    if (!ok)
      bad.push_back(std::string("FilmEnergySolver::Options::") + field + " = " +
                    internal::FormatReal(v) + " violates " + c);
  };
  rule(film_nodes >= 3, "film_nodes", film_nodes, ">= 3");
  rule(tolerance_k > 0, "tolerance_k", tolerance_k, "> 0 [K]");
  rule(max_iterations >= 1, "max_iterations", max_iterations, ">= 1");
  rule(relaxation > 0 && relaxation <= 1, "relaxation", relaxation, "in (0, 1]");
  rule(max_chord_steps >= 1, "max_chord_steps", max_chord_steps, ">= 1");
  rule(history_near_cells >= 0, "history_near_cells", history_near_cells, ">= 0");
  return bad;
}

FilmEnergySolver::FilmEnergySolver(const UniformGrid& grid,
                                   const Lubricant& lubricant,
                                   const SolidThermal& solid1,
                                   const SolidThermal& solid2,
                                   double inlet_temperature_k,
                                   const Options& options)
    : grid_(grid),
      lubricant_(&lubricant),
      solid1_(solid1),
      solid2_(solid2),
      t0_(inlet_temperature_k),
      options_(options) {
  ProblemList bad;
  for (const auto& m : options.Validate()) bad.Add({"", 0, "FilmEnergySolver::Options", "", m, ""});
  if (!(std::isfinite(t0_) && t0_ > 0))
    bad.Add({"", 0, "inlet_temperature_k", internal::FormatReal(t0_), "must be > 0",
             "an absolute temperature > 0 [K]"});
  if (options.walls == Walls::kMovingSolids) {
    try {
      MovingHeatSource::Factor(solid1, 1.0);
    } catch (const InputError& e) {
      bad.Append(e.problems());
    }
    try {
      MovingHeatSource::Factor(solid2, 1.0);
    } catch (const InputError& e) {
      bad.Append(e.problems());
    }
  }
  bad.ThrowIfAny();
}

FilmTemperature FilmEnergySolver::Initial() const {
  const int n = grid_.size(), nz = options_.film_nodes;
  FilmTemperature t;
  t.t_k = Eigen::MatrixXd::Constant(n, nz, t0_);
  t.t1_k = t.t2_k = Eigen::VectorXd::Constant(n, t0_);
  t.q1_w_m2 = t.q2_w_m2 = Eigen::VectorXd::Zero(n);
  return t;
}

namespace {

void CheckFlow(const FilmFlowField& f, int n, int nz, bool moving, ProblemList* bad) {
  auto size_rule = [&](const char* key, long rows, long cols, long want_cols) {
    if (rows != n || cols != want_cols) {
      std::ostringstream got, want;
      got << rows << " x " << cols;
      want << n << " x " << want_cols;
      bad->Add({"", 0, key, got.str(), "wrong size", want.str()});
      return false;
    }
    return true;
  };
  auto finite = [&](const char* key, bool ok) {
    if (!ok) bad->Add({"", 0, key, "non-finite", "must be finite", "finite values"});
  };
  if (size_rule("FilmFlowField::p_pa", f.p_pa.size(), 1, 1))
    finite("FilmFlowField::p_pa", f.p_pa.allFinite());
  if (size_rule("FilmFlowField::h_m", f.h_m.size(), 1, 1)) {
    finite("FilmFlowField::h_m", f.h_m.allFinite());
    if (f.h_m.allFinite() && !(f.h_m.minCoeff() > 0))
      bad->Add({"", 0, "FilmFlowField::h_m", internal::FormatReal(f.h_m.minCoeff()),
                "must be > 0 everywhere", "a film thickness > 0 [m]"});
  }
  if (f.dpdt_pa_s.size() && size_rule("FilmFlowField::dpdt_pa_s", f.dpdt_pa_s.size(), 1, 1))
    finite("FilmFlowField::dpdt_pa_s", f.dpdt_pa_s.allFinite());
  if (f.dhdt_m_s.size() && size_rule("FilmFlowField::dhdt_m_s", f.dhdt_m_s.size(), 1, 1))
    finite("FilmFlowField::dhdt_m_s", f.dhdt_m_s.allFinite());
  if (size_rule("FilmFlowField::u_m_s", f.u_m_s.rows(), f.u_m_s.cols(), nz))
    finite("FilmFlowField::u_m_s", f.u_m_s.allFinite());
  if (size_rule("FilmFlowField::heating_w_m3", f.heating_w_m3.rows(), f.heating_w_m3.cols(), nz)) {
    finite("FilmFlowField::heating_w_m3", f.heating_w_m3.allFinite());
    if (f.heating_w_m3.allFinite() && f.heating_w_m3.minCoeff() < 0)
      bad->Add({"", 0, "FilmFlowField::heating_w_m3",
                internal::FormatReal(f.heating_w_m3.minCoeff()), "must be >= 0",
                "a viscous dissipation >= 0 [W/m^3]"});
  }
  if (f.heating_decay_1_k.size() || f.heating_reference_t_k.size()) {
    if (size_rule("FilmFlowField::heating_decay_1_k", f.heating_decay_1_k.rows(),
                  f.heating_decay_1_k.cols(), nz) &&
        !(f.heating_decay_1_k.allFinite() && f.heating_decay_1_k.minCoeff() >= 0))
      bad->Add({"", 0, "FilmFlowField::heating_decay_1_k", "negative or non-finite",
                "must be finite and >= 0", "a heating decay rate >= 0 [1/K]"});
    if (size_rule("FilmFlowField::heating_reference_t_k", f.heating_reference_t_k.rows(),
                  f.heating_reference_t_k.cols(), nz) &&
        !(f.heating_reference_t_k.allFinite() && f.heating_reference_t_k.minCoeff() > 0))
      bad->Add({"", 0, "FilmFlowField::heating_reference_t_k", "non-positive or non-finite",
                "must be finite and > 0", "an absolute temperature > 0 [K]"});
  }
  if (moving)
    for (auto [key, u] : {std::pair{"FilmFlowField::u1_m_s", f.u1_m_s},
                          std::pair{"FilmFlowField::u2_m_s", f.u2_m_s}})
      if (!(std::isfinite(u) && u > 0))
        bad->Add({"", 0, key, internal::FormatReal(u), "must be > 0 with moving solids",
                  "a surface speed > 0 [m/s] in +x"});
}

// max |delta theta| over the film (the surface-flux unknowns excluded) [K].
double ChangeOfTemperatures(const Eigen::VectorXd& delta, int n, int nz) {
  double m = 0;
  for (int i = 0; i < n; ++i)
    m = std::max(m, delta.segment(i * (nz + 2), nz).cwiseAbs().maxCoeff());
  return m;
}

// Steps a linear contraction r needs from a step of size `change` until its remaining error
// change r^m / (1 - r) is below tol.
double ChordStepsToGo(double change, double r, double tol) {
  if (!(r > 0)) return 0;
  const double target = tol * (1 - r) / change;
  return target >= 1 ? 0 : std::log(target) / std::log(r);
}

}  // namespace

FilmEnergySolver::~FilmEnergySolver() = default;
FilmEnergySolver::FilmEnergySolver(FilmEnergySolver&&) noexcept = default;
FilmEnergySolver& FilmEnergySolver::operator=(FilmEnergySolver&&) noexcept = default;

FilmEnergySolver::Summary FilmEnergySolver::Solve(const FilmFlowField& flow,
                                                  const FilmTemperature* previous,
                                                  double dt_s,
                                                  FilmTemperature* t) const {
  return Solve(flow, previous, dt_s, options_.tolerance_k, t);
}

FilmEnergySolver::Summary FilmEnergySolver::Solve(const FilmFlowField& flow,
                                                  const FilmTemperature* previous,
                                                  double dt_s,
                                                  double tolerance_k,
                                                  FilmTemperature* t) const {
  const auto start = std::chrono::steady_clock::now();
  const int n = grid_.size(), nz = options_.film_nodes;
  const bool moving = options_.walls == Walls::kMovingSolids;
  const bool transient = dt_s > 0;
  ProblemList bad;
  CheckFlow(flow, n, nz, moving, &bad);
  if (!(tolerance_k > 0))
    bad.Add({"", 0, "tolerance_k", std::to_string(tolerance_k), "must be > 0", "> 0 [K]"});
  if (transient && (!previous || !previous->Matches(n, nz)))
    bad.Add({"", 0, "previous", previous ? "wrong size" : "null",
             "a transient step needs the previous level", "a FilmTemperature of n x nz"});
  bad.ThrowIfAny();

  internal::FilmEnergyInputs in;
  in.flow = &flow;
  in.previous_t_k = transient ? &previous->t_k : nullptr;
  in.dt_s = dt_s;
  in.cp_j_kgk = lubricant_->heat_capacity_j_kgk();
  in.t0_k = t0_;
  in.fixed_walls = !moving;
  if (moving) {
    in.factor1 = MovingHeatSource::Factor(solid1_, flow.u1_m_s);
    in.factor2 = MovingHeatSource::Factor(solid2_, flow.u2_m_s);
    if (options_.finite_peclet) {
      in.omega1 = MovingHeatSource::DecayRate(solid1_, flow.u1_m_s);
      in.omega2 = MovingHeatSource::DecayRate(solid2_, flow.u2_m_s);
    }
  }
  // The solids' heat history (high-Peclet moving solids; finite-Peclet ones are quasi-steady).
  internal::StepHistory history;
  if (moving && transient && !options_.finite_peclet) {
    history = internal::HistoryOfStep(grid_, *previous, dt_s, flow.u1_m_s, flow.u2_m_s);
    if (history.active) {
      in.reach1_m = history.reach1_m;
      in.reach2_m = history.reach2_m;
      in.history1 = &history.history1;
      in.history2 = &history.history2;
    }
  }
  if (!t->Matches(n, nz)) *t = Initial();
  if (!system_ || !options_.reuse_factorization) {
    system_ = std::make_unique<internal::FilmEnergySystem>(grid_, nz, options_.history_near_cells,
                                                           options_.finite_peclet);
    krylov_steps_ = false;
    last_krylov_step_ = 0;
  }
  internal::FilmEnergySystem& system = *system_;
  const int krylov_before = system.krylov_iterations();

  // Lubricant properties: k(p) per column, rho(p, T) per node at the current iterate.
  Eigen::VectorXd p = flow.p_pa.cwiseMax(0.0), k(n);
  for (int i = 0; i < n; ++i) k[i] = lubricant_->conductivity().Evaluate(p[i]).k_w_mk;
  internal::CellMatrix rho(n, nz), drho_dt(n, nz), drho_dp(n, nz);
  Eigen::VectorXd x = system.Pack(*t, t0_), delta;

  // Picard on the temperature dependence of rho; each step x += w A_f^-1 (b(x) - A(x) x) with
  // A_f the latest factorization (a chord step when A_f is older than A(x)).
  Summary s;
  s.message = "";
  double last_change = std::numeric_limits<double>::infinity();
  bool last_fresh_exact = false;  // the previous step had a fresh factorization of the full A
  int poor_after_exact = 0;       // poor steps right after one
  // Once the lagged history stalls the chord steps (below), the rest of the steps are Krylov
  // steps: GMRES on the whole operator (FilmEnergySystem::Correction). So are all steps of the
  // later Solves on the same system: the coupling loop re-solves a slowly changing film, and
  // rediscovering the stall cost every Solve two fresh factorizations and two diverging chord
  // steps (taken, tens of kelvin) that the Krylov steps then had to undo (docs/performance.md,
  // "Energy solves on fine grids").
  bool krylov = krylov_steps_ && system.lags_far_history();
  for (int it = 1; it <= options_.max_iterations; ++it) {
    bool linear = true;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < nz; ++j) {
        const DensityValue d = lubricant_->density().Evaluate(p[i], t->t_k(i, j));
        rho(i, j) = d.rho_kg_m3;
        drho_dt(i, j) = d.drho_dT;
        drho_dp(i, j) = d.drho_dp;
        linear = linear && d.drho_dT == 0;
      }
    linear = linear && flow.heating_decay_1_k.size() == 0;
    system.Assemble(in, t->t_k, rho, drho_dt, drho_dp, k);
    bool fresh = false, ok = true;
    auto factorize = [&](bool exact) {
      fresh = true;
      ++s.factorizations;
      return system.Factorize(exact);
    };
    const bool after_exact = last_fresh_exact;
    // First the cheap factorization without the reverse-flow couplings (exact when there is
    // no reverse flow).
    if (!system.HasFactorization()) ok = factorize(false);
    // A Krylov step preconditioned by an old factorization takes more GMRES iterations the
    // more the film has moved since: past kKrylovRefresh in the last step, factorize afresh,
    // without the history inside recirculation zones (GMRES carries all of A; the cheaper
    // factors cost fewer triangular solves than the exact ones save in GMRES iterations).
    if (ok && krylov && last_krylov_step_ > kKrylovRefresh) ok = factorize(false);
    const int krylov_done = system.krylov_iterations();
    ok = ok && system.Correction(x, krylov, &delta);
    if (krylov) last_krylov_step_ = system.krylov_iterations() - krylov_done;
    double change = ok ? ChangeOfTemperatures(delta, n, nz) : 0.0;
    // A step that fails, or whose contraction r = change / last_change would need more than
    // max_chord_steps further steps to reach the tolerance, is redone with a fresh factorization
    // of the full A, unless it already had one (then what remains is the Picard nonlinearity).
    double r = change / last_change;
    const bool poor =
        !ok || r >= 1 || ChordStepsToGo(change, r, tolerance_k) > options_.max_chord_steps;
    if (poor && !(fresh && system.factorized_exact())) {
      // Poor twice right after a factorization of the full sparse A (at once with finite
      // Peclet numbers, whose upstream history is lagged too): what converges slowly is the
      // history lagged outside A (a solid strongly coupled to the film), so the rest of the
      // steps solve with it, by GMRES preconditioned with the factorization. Taking the whole
      // history into A instead, as before, made KLU's factors dense triangles: the 1025-node
      // seed 004 cycle took 19.9 s instead of 9.0 s (docs/performance.md).
      if (system.lags_far_history() &&
          (options_.finite_peclet || (after_exact && ++poor_after_exact >= 2))) {
        krylov = true;
        // Sticky only where the chord steps diverged (r >= 1), with the high-Peclet history.
        // Where they merely converge slowly, or with finite Peclet numbers (the switch costs
        // one step there), chord steps are cheaper in the later Solves: Krylov steps
        // throughout took the 1025-node seed 004 cycle from 6.9 to 9.8 s and the main job with
        // finite_peclet from 3.2 to 4.2 s (docs/performance.md).
        krylov_steps_ = !options_.finite_peclet && r >= 1;
      }
      const int before = system.krylov_iterations();
      ok = factorize(true) && system.Correction(x, krylov, &delta);
      if (krylov) last_krylov_step_ = system.krylov_iterations() - before;
      if (ok) change = ChangeOfTemperatures(delta, n, nz);
      r = 0;
    }
    if (!ok) {
      s.termination = Termination::kLinearSolverFailed;
      s.message = "KLU could not factor or solve the energy system (singular or non-finite)";
      break;
    }
    s.iterations = it;
    last_fresh_exact = fresh && system.factorized_exact();
    x += options_.relaxation * delta;
    system.Unpack(x, t0_, t);
    // Nothing depends on T when d rho/dT = 0: a step with a fresh factorization is the solution.
    const bool exact_step = fresh && system.factorized_exact() && !system.lags_far_history() &&
                            !system.lags_couplings();
    s.max_change_k = (linear && exact_step && options_.relaxation == 1.0) ? 0.0 : change;
    last_change = change;
    // Remaining error of a contraction r after a step of size `change`: change r / (1 - r).
    if (s.max_change_k * std::max(1.0, r / (1 - r)) < tolerance_k) {
      s.termination = Termination::kConverged;
      break;
    }
    s.termination = Termination::kMaxIterations;
  }
  s.krylov_iterations = system.krylov_iterations() - krylov_before;
  if (moving && transient && !options_.finite_peclet) {
    internal::RememberLevels(grid_, *previous, dt_s, flow.u1_m_s, flow.u2_m_s, t);
  } else {
    internal::ForgetLevels(flow.u1_m_s, flow.u2_m_s, t);
  }
  if (s.iterations > 0) {
    s.balance = system.Balance(in, *t);
    s.mass_defect = system.mass_defect();
  }
  if (s.termination == Termination::kMaxIterations) {
    std::ostringstream m;
    m << "no convergence in " << options_.max_iterations << " Picard iterations (last change "
      << s.max_change_k << " K > tolerance " << tolerance_k << " K)";
    s.message = m.str();
  }
  s.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return s;
}

}  // namespace tehl

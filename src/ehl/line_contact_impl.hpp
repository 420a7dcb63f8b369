// The private implementation of LineContactSolver (include/tehl/ehl/line_contact_solver.hpp):
// the member functions are defined by concept in line_contact_solver.cpp (construction, film),
// line_contact_pressure.cpp (pressure Newton, continuation, grid sequencing),
// line_contact_transient.cpp (time stepping), line_contact_coupling.cpp (the thermal coupling:
// alternation and coupled grid sequencing), line_contact_coupling_newton.cpp (Newton-Krylov
// on the coupling map) and line_contact_friction.cpp; the options, names and summary are in
// line_contact_options.cpp. Private to src/ehl.
#pragma once

#include <Eigen/Core>
#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ehl/film_field.hpp"
#include "ehl/fixed_point_newton.hpp"
#include "ehl/newton_system.hpp"
#include "ehl/reynolds_system.hpp"
#include "tehl/ehl/elastic_deflection.hpp"
#include "tehl/ehl/line_contact_solver.hpp"

namespace tehl::internal {

// Copies the time and the travel of both surfaces (where rough surfaces are sampled): a
// guess that replaces a state keeps them.
inline void CopyClock(const FilmState& from, FilmState* to) {
  to->time_s = from.time_s;
  to->travel1_m = from.travel1_m;
  to->travel2_m = from.travel2_m;
}

}  // namespace tehl::internal

namespace tehl {

class LineContactSolver::Impl {
 public:
  Impl(const UniformGrid& grid,
       double e_prime,
       const Lubricant& lub,
       const FilmEffects& eff,
       const Options& opt,
       std::shared_ptr<const SurfaceShape> s1,
       std::shared_ptr<const SurfaceShape> s2,
       const ContactSolids& solids);

  const UniformGrid& grid() const { return grid_; }
  const Options& options() const { return opt_; }

  internal::FluidLaws Fluid(const ContactConditions& c, double pressure_scale = 1.0) const;
  // Film h = h0 + x^2/(2R) + v(p) - heights at the state's travel.
  void Film(const ContactConditions& c, FilmState* s) const;

  struct Scales {
    double p_ref, h_ref;
  };

  Scales ScalesFor(const ContactConditions& c) const;
  double EstimateCentralFilm(const ContactConditions& c) const;
  // For a failed solve with roughness: when the surfaces' heights span more than the smooth
  // film of the conditions, a sentence saying so for its message; "" otherwise.
  std::string RoughnessHint(const ContactConditions& c, const FilmState& s) const;
  // For the message of a failed steady solve: when the grid does not span the Hertzian edge of
  // the film that Moes' fit estimates (hertz_edge.hpp), says so and how many nodes would;
  // else empty.
  std::string EdgeHint(const ContactConditions& c) const;
  // `clock`: the state whose time and travel the guess takes (rough surfaces are sampled at
  // the travel); null = time and travel 0.
  FilmState InitialGuess(const ContactConditions& c, const FilmState* clock = nullptr) const;
  // Row weights c_i = -1/|dr_i/dP_i| at the current linearization: the complementarity
  // min(P_i, c_i r_i) then compares two quantities of the same size (a pressure change),
  // however much rho h^3/(12 eta) varies along the film. Negative because the cavitated
  // branch has -r >= 0: a divergent gap could carry more flow than arrives.
  void UpdateRowWeights(const Scales& sc);
  internal::NewtonSystem SystemFor(const Scales& sc, double load) const;
  // Scaled residual F(z) of a state; false if the film is not positive or not finite.
  // `linearize` also refreshes the derivatives and, unless `refresh_weights` is false, the row
  // weights.
  bool Residual(const ContactConditions& c,
                const internal::FluidLaws& fluid,
                const Scales& sc,
                const internal::TimeDerivative& td,
                FilmState* s,
                Eigen::VectorXd* f,
                bool linearize,
                bool refresh_weights = true);
  // F(z) from the Reynolds residual last evaluated (for state s) and the current row weights;
  // sets cavitated_. False if not finite.
  bool ComplementarityResidual(const ContactConditions& c,
                               const Scales& sc,
                               const FilmState& s,
                               Eigen::VectorXd* f);
  Summary Newton(const ContactConditions& c,
                 double pressure_scale,
                 const internal::TimeDerivative& td,
                 FilmState* s);
  Summary Finish(const ContactConditions& c, FilmState* s, Summary sum);
  bool ValidConditions(const ContactConditions& c, Summary* sum) const;
  // Newton, then continuation in load and pressure-viscosity coefficient if it fails.
  Summary Solve(const ContactConditions& c, const internal::TimeDerivative& td, FilmState* s);
  // Grid sequencing: without a usable guess, solve on a grid with half the cells (down to
  // opt_.coarse_grid_nodes) and interpolate. A damped Newton method moves the cavitation
  // boundary about one node per iteration, so the fine grid should start next to it.
  // The guess keeps the time and travel of `clock` (the state it replaces).
  FilmState SequencedGuess(const ContactConditions& c,
                           const internal::TimeDerivative& td,
                           const FilmState& clock);

  // --- transient ----------------------------------------------------------------------
  struct History {
    int levels = 0;              // stored levels (1 to 3)
    Eigen::VectorXd q1, q2, q3;  // rho h at t_{n-1}, t_{n-2}, t_{n-3}
    double dt_prev = 0;        // t_{n-1} - t_{n-2}
    double dt_prev2 = 0;       // t_{n-2} - t_{n-3}
    double h_next = 0;         // time-error control: the next substep's proposed size (0: none)
    ContactConditions c_prev;  // conditions at t_{n-1}
    Eigen::MatrixXd t_prev;    // film temperature at t_{n-2} (thermal; empty before) [K]
  };

  Eigen::VectorXd RhoH(const ContactConditions& c, FilmState s);
  void BeginTransient(const ContactConditions& c, const FilmState& s);
  internal::TimeDerivative Derivative(double dt) const;
  // A step's estimated local time error [-] (-1: not estimated) and its order in dt (3 for
  // rho h under BDF2, 2 under BDF1 and for the temperature).
  struct TimeError {
    double value = -1;
    double order = 3;
  };
  // One step of dt to the conditions c; *time_error: the larger of LocalTimeError and, in
  // thermal runs, TemperatureTimeError (value -1 when not estimated or not converged).
  Summary OneStep(const ContactConditions& c, double dt, FilmState* s, TimeError* time_error);
  // Thermal runs: the local error of the film temperature (BDF1 in the energy equation) by
  // Milne's device on the temperatures of the last two levels, T_n = t_n and hist_.t_prev:
  // the root mean square over the film nodes of the loaded nodes, relative to the film's
  // largest rise above the inlet temperature (at least 1 K) [-]; -1 without the levels.
  double TemperatureTimeError(double dt,
                              const Eigen::MatrixXd& t_n,
                              const ContactConditions& c,
                              const FilmState& next) const;
  // Milne's estimate of the local error of a step of dt that gave rho h = q and pressure p,
  // from the history before the step: the difference between q and the polynomial through
  // the last levels extrapolated to the new time (quadratic for BDF2, linear for BDF1), scaled
  // by the ratio of the error constants; the root mean square of error / q over the loaded
  // interior nodes [-], or -1 without enough levels (docs/theory.md, "Time-step error").
  double LocalTimeError(double dt, const Eigen::VectorXd& q, const Eigen::VectorXd& p) const;
  // Newton's start after the conditions changed from c_old to c: the pressure scaled by Hertz
  // similarity (half-width and peak), the central film by the film fit's ratio. Only when the
  // outlet would otherwise be more than a cell away; false (s untouched) otherwise.
  bool PredictHertzSimilar(const ContactConditions& c_old, const ContactConditions& c,
                           FilmState* s) const;
  // The coupling's starting temperature for a step: linear in time through the last two
  // levels (the energy equation's old level stays the state's). Measured on the thermal
  // seed 004 cycle: fewer coupling iterations per step than starting from the last level.
  void ExtrapolateTemperature(double dt, const FilmState& s, FilmState* next) const;
  Summary Step(const ContactConditions& c_new,
               double dt,
               FilmState* s,
               const ContactConditions* c_start);
  // The conditions a fraction f of the way from a to b (linear in each).
  static ContactConditions Interpolate(const ContactConditions& a,
                                       const ContactConditions& b,
                                       double f);
  // Step without time-error control: one piece, and 2 and then 4 equal substeps where it does
  // not converge; after substeps the history keeps the whole-step levels.
  Summary SubstepLadder(const ContactConditions& c_new,
                        double dt,
                        FilmState* s,
                        const ContactConditions* c_start);
  // Step under time-error control (Options::time_tolerance > 0): substeps sized by the local
  // error estimate (line_contact_adaptive_step.cpp).
  Summary AdaptiveStep(const ContactConditions& c_new,
                       double dt,
                       FilmState* s,
                       const ContactConditions* c_start);
  double ResidualNorm(const ContactConditions& c, const FilmState& st);
  Eigen::VectorXd MassFlow(const ContactConditions& c, const FilmState& st);
  TransientHistory SaveTransient() const;
  void RestoreTransient(const TransientHistory& h);
  FilmFriction Friction(const ContactConditions& c, const FilmState& st);

  struct CouplingNewton {
    internal::FixedPointNewtonResult result;
    Summary pressure;     // the last pressure solve (at the returned temperature)
    double balance = -1;  // energy balance error of the last energy solve [-]
    EnergyBalance energy;  // and its budget [W/m]
  };
  // Newton-Krylov on x = G(x), x = the film temperature (and w log f of the Eyring factor in
  // Ree-Eyring runs), G = the energy solve (and the factor) at the pressure solved with the
  // film at x (ehl/fixed_point_newton.hpp), from the field's state and the state *s; on
  // return *s holds the pressure solved at the last x, which the field holds.
  CouplingNewton NewtonCoupling(const ContactConditions& c,
                                const internal::TimeDerivative& td,
                                const FilmState* previous,
                                double dt_s,
                                FilmState* s);
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
                       const internal::TimeDerivative& td,
                       const FilmState* previous,
                       double dt_s,
                       FilmState* s);
  // A state of grid g interpolated linearly onto this grid: pressure, rigid approach and (when
  // present) the film temperature, node row by node row.
  // cs on grid g, interpolated onto this grid (with cs's time and travel).
  FilmState Interpolated(const UniformGrid& g, const FilmState& cs, const ContactConditions& c);
  // One coupled solve from *s: the alternation, then (newton: when it stalls) Newton on the
  // coupling.
  Summary CoupleOnce(const ContactConditions& c,
                     const internal::TimeDerivative& td,
                     const FilmState* previous,
                     double dt_s,
                     bool newton,
                     FilmState* s);

 private:
  UniformGrid grid_;
  double e_prime_;
  const Lubricant& lub_;
  FilmEffects eff_;
  Options opt_;
  std::shared_ptr<const SurfaceShape> s1_, s2_;
  ContactSolids solids_;
  internal::ReynoldsSystem sys_;
  std::optional<ElasticDeflection> elastic_;
  std::unique_ptr<internal::NewtonLinearSolver> linear_;
  Eigen::VectorXd x2_, row_weight_;
  Eigen::VectorXd diagonal_;  // UpdateRowWeights: the Jacobian's diagonal [1/Pa scaled r]
  mutable Eigen::VectorXd heights_;
  // The travels (surface 1, 2) heights_ was sampled at [m]; NaN: not sampled yet.
  mutable std::array<double, 2> heights_travel_m_ = {std::numeric_limits<double>::quiet_NaN(),
                                                     std::numeric_limits<double>::quiet_NaN()};
  std::vector<char> cavitated_;
  History hist_;
  std::unique_ptr<Impl> coarse_;                // grid sequencing, built on first use
  std::unique_ptr<Impl> thermal_coarse_;        // coupled grid sequencing, built on first use
  std::unique_ptr<internal::FilmField> field_;  // thermal / non-Newtonian runs only
};

}  // namespace tehl

// Isothermal elastohydrodynamic line contact: transient compressible Reynolds equation,
// DC-FFT elastic deflection, Dowson-Higginson density and the lubricant's viscosity law,
// solved by Newton-Raphson on (p, h0) with the load balance (DESIGN.md sections 4-5, seed 004
// eqs. 2-8; docs/theory.md gives the discretization).
//
// Unknowns: pressure p_i at the interior nodes of a UniformGrid and the rigid approach h0.
//   Reynolds   d/dx(rho h^3/(12 eta) dp/dx) - um d(rho h)/dx - d(rho h)/dt = 0   where p > 0,
//   cavitation p >= 0 with the residual >= 0 where p = 0 (a complementarity, solved by a
//              semismooth Newton method on min(p, r): the Reynolds exit condition emerges),
//   film       h = h0 + x^2/(2R) + v(x) - height1(x, t) - height2(x, t),
//   load       integral p dx = w.
// Gear-free: R, u1, u2, w and the surface shapes are plain inputs at each instant.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tehl/ehl/elastic_deflection.hpp"
#include "tehl/ehl/film_effects.hpp"
#include "tehl/ehl/film_energy.hpp"
#include "tehl/ehl/grid.hpp"
#include "tehl/ehl/surface_temperature.hpp"

namespace tehl {

class Lubricant;
class SurfaceShape;

// kDense: a fresh dense LU per Newton iteration (the reference). kNewtonKrylov: GMRES with the
// sparse LU of an augmented film system as preconditioner. kReusedLu: GMRES preconditioned
// by the dense LU of an earlier Jacobian, refactorized only when GMRES needs more than
// reused_lu_max_gmres iterations.
// kAuto: kReusedLu up to dense_max_nodes, kNewtonKrylov above.
enum class LinearSolverKind { kAuto, kDense, kNewtonKrylov, kReusedLu };
std::string ToString(LinearSolverKind k);
LinearSolverKind LinearSolverKindFromString(const std::string& s);  // throws InputError

enum class TimeScheme { kBdf1, kBdf2 };
std::string ToString(TimeScheme s);
TimeScheme TimeSchemeFromString(const std::string& s);  // throws InputError

// The operating state of the contact at one instant.
struct ContactConditions {
  double reduced_radius_m = 0;  // R, 1/R = 1/rho1 + 1/rho2 [m]
  double u1_m_s = 0;            // surface speed of body 1 relative to the contact point [m/s]
  double u2_m_s = 0;            // surface speed of body 2 [m/s]
  double load_n_per_m = 0;      // w, load per unit face width [N/m]
  double temperature_k = 0;     // film temperature (inlet temperature when isothermal) [K]
  double um() const { return 0.5 * (u1_m_s + u2_m_s); }  // entrainment speed [m/s]
};

// Thermal properties of the two bodies (used only when effects.thermal is on).
struct ContactSolids {
  SolidThermal body1{7850.0, 470.0, 46.0};  // steel by default
  SolidThermal body2{7850.0, 470.0, 46.0};
};

// Friction of the film (seed 004 eq. 16): the shear force of the film on each surface per unit
// face width, from the wall shear stress of the cross-film velocity profile.
struct FilmFriction {
  double traction1_n_per_m = 0;  // integral tau(z = 0) dx: force on surface 1 along +x [N/m]
  double traction2_n_per_m = 0;  // -integral tau(z = h) dx: force on surface 2 along +x [N/m]
  double coefficient = 0;        // mu = (|traction1| + |traction2|) / (2 w) [-]
  double max_shear_stress_pa = 0;  // largest |tau| at either wall [Pa]
};

// The film at one time level (the solver's output and its next initial guess).
struct FilmState {
  Eigen::VectorXd p_pa;      // pressure at every node, zero at both ends [Pa]
  Eigen::VectorXd h_m;       // film thickness at every node [m]
  double h0_m = 0;           // rigid approach [m]
  double time_s = 0;         // time of this level [s]
  double travel1_m = 0;      // integral of u1 dt since t = 0: how far surface 1 moved [m]
  double travel2_m = 0;      // integral of u2 dt [m]
  // Thermal runs only (empty, nothing allocated, when effects.thermal is off): the film
  // temperature T(x_i, xi_j), the surface temperatures and the heat fluxes into the solids.
  FilmTemperature temperature;
  // The conditions of the solve that produced this state (set by SolveSteady and Step when they
  // converge). A later SolveSteady under other conditions starts from this state scaled by
  // Hertz similarity when the contact's outlet moves by more than a grid cell.
  std::optional<ContactConditions> solved_for;
  bool valid() const { return p_pa.size() > 0 && p_pa.size() == h_m.size(); }
  // The film's scalars. They describe a state with a film: on one that is not valid() (never
  // solved) they return 0, which is no film thickness; check valid() first. (The solver's
  // diagnostics below return NaN, or an empty vector, for such a state instead.)
  double MinFilm() const;  // h_min, parabola through the smallest node (that node if the
                           // parabola dips below zero between positive nodes) [m]
  double CentralFilm(const UniformGrid& g) const;  // h at x = 0 (interpolated) [m]
  double MaxPressure() const;  // p_max [Pa]
};

class LineContactSolver {
 public:
  struct Options {
    LinearSolverKind linear_solver = LinearSolverKind::kAuto;
    int dense_max_nodes = 257;        // kAuto uses the reused dense LU up to this many
                                      // nodes, Newton-Krylov above [-] (measured switch
                                      // point: docs/performance.md)
    int upwind_order = 2;             // Couette-term upwinding: 1 or 2 [-]
    TimeScheme time_scheme = TimeScheme::kBdf2;
    // Transient steps: the largest local error a substep may leave, relative (Milne's
    // estimate, Summary::time_error). With it > 0 each step is integrated in substeps sized by
    // the estimate (at most twice the one before, at least 1/4096 of the step); 0 = one piece,
    // and 2 or 4 substeps only where a step does not converge (docs/theory.md, "Time-step
    // error") [-].
    double time_tolerance = 0;
    double tolerance = 1e-8;          // stop when the scaled residual max-norm < this [-]
    int max_iterations = 100;         // Newton iterations per solve [-]
    int gmres_restart = 60;           // Krylov vectors before a restart [-]
    int gmres_max_iterations = 400;   // per Newton step [-]
    int reused_lu_max_gmres = 20;     // kReusedLu refactorizes beyond this [-]
    int preconditioner_band = 8;      // Newton-Krylov: half-band of the second-differenced
                                      // elastic kernel per preconditioner level [-]
    int preconditioner_coarse_pressures = 128;  // Newton-Krylov: coarse size c of the
                                      // two-level preconditioner (c to 2c pressures, one per
                                      // 16 cells in between); 0 = the UMFPACK hierarchy of
                                      // strides instead (docs/performance.md) [-]
    int preconditioner_inlet_hats = 8;  // Newton-Krylov, c > 0, where c to 2c uniform hats
                                        // are >= 8 cells apart (2049 nodes and up at c = 128):
                                        // hats on a lattice of half their stride, this many
                                        // lattice cells wide before the elastic zone (about
                                        // 1.5 b before the centre); 1 = uniform hats
                                        // (docs/theory.md) [-]
    int preconditioner_outlet_refresh = 16;  // Newton-Krylov, c > 0: at each Newton
                                             // iteration the kept band factorization is redone
                                             // from n / this many nodes before the outlet (or the
                                             // first node whose cavitation changed) on; 0 = never
                                             // (docs/performance.md) [-]
    int max_continuation_stages = 12; // load / pressure-viscosity continuation stages [-]
    int coarse_grid_nodes = 129;      // grid sequencing halves the grid down to this [-]
    double min_step_fraction = 1.0 / 1024;  // smallest line-search step [-]
    // When the conditions change so much that the outlet moves by more than a grid cell, start
    // Newton from the last solution scaled by Hertz similarity (docs/theory.md, "Warm starts"):
    // a cavitation boundary otherwise advances by about one cell per Newton iteration.
    bool predict_hertz_similar = true;
    // FFTW planning of this grid's deflection (elastic_deflection.hpp): kMeasure (the
    // default) for the many deflections of a solver's life; the coarse grids of the grid
    // sequencing, used for a few Newton iterations of a cold solve, always plan with
    // kEstimate (measuring their sizes took about as long as the whole cold solve at 4097
    // nodes: docs/performance.md).
    FftPlanEffort fft_plan_effort = FftPlanEffort::kMeasure;
    // Iterative linear solvers: GMRES stops at the Eisenstat-Walker forcing term (choice 2,
    // gamma 0.9, alpha 2, at most 1e-3) instead of a fixed 1e-10 (docs/theory.md).
    bool inexact_newton = true;
    // Thermal runs: the pressure solve and the energy solve alternate (the temperature
    // under-relaxed) until the temperature changes by less than thermal_tolerance_k.
    int film_nodes = 11;              // nodes across the film, both surfaces included [-]
    double thermal_tolerance_k = 0.01;     // [K]
    double coupling_pressure_tolerance = 1e-4;  // non-Newtonian: max |p change| / p_max [-]
    int max_coupling_iterations = 40;      // [-]
    // A coupling still converging after max_coupling_iterations (its smallest change over
    // the last 10 iterations below that over the 10 before, at a rate that reaches the
    // tolerance within this many iterations: the temperature change in thermal runs, the
    // pressure change otherwise) goes on, up to this many; not where Newton on the coupling
    // takes over instead (Newtonian thermal runs) [-].
    int max_coupling_iterations_converging = 160;
    double thermal_relaxation = 0.8;       // T <- T + relaxation (T_energy - T) [-]
    // Newtonian thermal runs: when the alternation has not reduced its temperature change
    // for this many iterations (or has used them all), Newton-Krylov on the coupling takes
    // over from the best iterate (docs/theory.md, "Thermal coupling"); 0 = never [-].
    int coupling_newton_after = 6;
    // Isothermal Ree-Eyring films: each coupling iteration takes an Anderson step on log f
    // (docs/thermal.md "Ree-Eyring film"); false: the relaxed step, half-way in log f.
    bool eyring_anderson = true;
    std::vector<std::string> Validate() const;  // every violated rule; empty = valid
  };

  enum class Termination { kConverged, kMaxIterations, kLineSearchFailed, kLinearSolverFailed,
                           kInvalidInput, kCouplingNotConverged };
  struct IterationRecord {
    double residual = 0;       // scaled max-norm after the iteration [-]
    double step = 0;           // line-search step taken (1 = full Newton) [-]
    int krylov_iterations = 0; // GMRES iterations (0 for dense LU) [-]
    int cavitated_nodes = 0;   // nodes on the p = 0 branch [-]
  };
  struct Summary {
    Termination termination = Termination::kInvalidInput;
    std::string message = "not solved yet (SolveSteady or Step was not called)";
    int iterations = 0;             // Newton iterations of the final stage [-]
    int total_iterations = 0;       // including continuation stages [-]
    int continuation_stages = 0;    // 0 = solved directly [-]
    int krylov_iterations = 0;      // total GMRES iterations [-]
    double residual = -1;           // final scaled residual max-norm [-]
    double load_error = -1;         // |integral p dx - w| / w [-]
    double wall_time_s = 0;         // [s]
    std::string linear_solver;      // "dense", "newton_krylov" or "reused_lu"
    int substeps = 1;               // time substeps a transient Step needed [-]
    // Transient steps: the estimated local error of rho h relative to rho h (in thermal runs
    // the larger of that and the film temperature's error relative to its rise), the largest
    // over the step's substeps (Options::time_tolerance); -1 where not estimated (the first
    // two steps of BDF2, the first of BDF1, steady solves) [-].
    double time_error = -1;
    std::vector<IterationRecord> history;
    // Thermal runs: pressure/energy coupling iterations, the last temperature change and the
    // energy balance error of the film (EnergyBalance::RelativeError) [-]; -1 where not
    // computed (also after an energy solve that gave a non-finite temperature).
    int coupling_iterations = 0;    // [-]
    double temperature_change_k = -1;  // [K]
    double energy_balance_error = -1;  // [-]
    // Where the film's heat goes, from its last energy solve (thermal runs; zeros otherwise):
    // generated by shear and compression, convected out through the ends, conducted into
    // solid 1 and solid 2, stored (transient steps) [W/m].
    EnergyBalance energy;
    int coupling_newton_iterations = 0;  // Newton steps on the coupling (0 = not needed) [-]
    int temperature_backoffs = 0;  // halvings of coupling temperature steps whose pressure
                                   // solve failed (docs/thermal.md) [-]
    // A converged film whose pressure is still positive at the grid's last inner node: its
    // outlet (the Reynolds exit) lies beyond the grid, which ends inside the film and cuts
    // it (a grid sized for a smaller load or a lighter, thicker film). The film is a solution
    // of the cut problem, not of the contact: size the grid for the largest half-width.
    bool outlet_cut = false;
    bool usable() const { return termination == Termination::kConverged; }
    std::string BriefReport() const;
  };

  // e_prime_pa: the plane-strain modulus E' with 2/E' = (1-nu1^2)/E1 + (1-nu2^2)/E2, which is
  // twice Johnson's E* (ReducedModulus in units.hpp) [Pa]. The lubricant and surface shapes
  // must outlive the solver (a temporary lubricant does not compile). surface1/2 may be null
  // (smooth); they are used only when effects.roughness is on. Throws InputError for a bad
  // grid, modulus or Options (Options::Validate).
  LineContactSolver(const UniformGrid& grid, double e_prime_pa, const Lubricant& lubricant,
                    const FilmEffects& effects, const Options& options,
                    std::shared_ptr<const SurfaceShape> surface1 = nullptr,
                    std::shared_ptr<const SurfaceShape> surface2 = nullptr,
                    const ContactSolids& solids = ContactSolids{});
  LineContactSolver(const UniformGrid&,
                    double,
                    const Lubricant&&,
                    const FilmEffects&,
                    const Options&,
                    std::shared_ptr<const SurfaceShape> = nullptr,
                    std::shared_ptr<const SurfaceShape> = nullptr,
                    const ContactSolids& = ContactSolids{}) = delete;
  ~LineContactSolver();
  LineContactSolver(LineContactSolver&&) noexcept;
  LineContactSolver& operator=(LineContactSolver&&) noexcept;

  const UniformGrid& grid() const;
  const Options& options() const;

  // A first guess: Hertz pressure (scaled onto the grid) and h0 from the Moes film fit.
  FilmState InitialGuess(const ContactConditions& c) const;

  // Bad conditions (R, w, um not finite and > 0; T outside kMinAbsoluteTemperatureK ..
  // kMaxTemperatureK) and a
  // state that is null or not of this grid end the solve at once with
  // Termination::kInvalidInput and say why in the Summary's message; nothing is thrown. The
  // solver takes any load (M = 5000 runs converge); case files refuse loads whose Hertz
  // half-width exceeds kMaxHertzWidthRatio R, and so should a caller that sizes its grid
  // from such a load.
  //
  // Steady solve. state: the initial guess on entry when valid() (else the interpolated
  // solution on a grid of half the cells, recursively, down to the InitialGuess on a grid of
  // about coarse_grid_nodes), the solution on exit. On failure the state holds the best iterate
  // found and the Summary says why; it never holds NaN.
  Summary SolveSteady(const ContactConditions& c, FilmState* state);

  // Transient: BeginTransient records the state at t0 (under conditions c) as history; each
  // Step advances to state->time_s + dt with the conditions at the new time (BDF1 for the
  // first step, then the chosen scheme, variable steps allowed). A step that fails is
  // retried as 2 and then 4 substeps with linearly interpolated conditions (reported in the
  // Summary), and with Options::time_tolerance > 0 a step whose estimated error is above it
  // is done again in more substeps; after substeps the history keeps the whole-step levels. With
  // effects.transient off, Step is a steady solve at the new conditions (the surfaces still
  // move).
  // Throws InputError when `initial` is not a film of this grid. Step begins by itself from
  // `state` when BeginTransient was not called.
  void BeginTransient(const ContactConditions& c, const FilmState& initial);
  // c_start: the conditions just after the current level where they jump there (the load
  // at B and D of a mesh cycle); the step, and its substeps, then go from c_start to c_new
  // instead of from the conditions of the last level.
  Summary Step(const ContactConditions& c_new,
               double dt_s,
               FilmState* state,
               const ContactConditions* c_start = nullptr);

  // The transient history (the stored levels of rho_e h, the last step and conditions), for
  // checkpoints: a solver restored with RestoreTransient and the state of the same time level
  // continues as the original would (to the solver tolerance: factorizations are rebuilt).
  struct TransientHistory {
    int levels = 0;                // stored levels (0: BeginTransient not called) [-]
    Eigen::VectorXd q1, q2, q3;    // rho_e h at t_{n-1}, t_{n-2}, t_{n-3} [kg/m^2]
    double dt_prev_s = 0;          // t_{n-1} - t_{n-2} [s]
    double dt_prev2_s = 0;         // t_{n-2} - t_{n-3} [s]
    double next_substep_s = 0;     // time-error control: the next substep's size (0: none) [s]
    ContactConditions c_prev;      // conditions at t_{n-1}
    Eigen::MatrixXd t_prev_k;      // film temperature at t_{n-2}, n x nz (thermal) [K]
  };
  TransientHistory SaveTransient() const;
  void RestoreTransient(const TransientHistory& h);

  // Diagnostics: the scaled steady residual max-norm of a state under conditions c, and
  // the mass flow per unit width q = rho h um - rho h^3/(12 eta) dp/dx between nodes i and
  // i+1 (size n-1) [kg/(m s)]; constant along x for a converged steady film. A state that is
  // not of this grid gives NaN and an empty vector.
  double ResidualNorm(const ContactConditions& c, const FilmState& state) const;
  Eigen::VectorXd MassFlow(const ContactConditions& c, const FilmState& state) const;

  // Friction of a solved state (its temperature field when thermal, else the inlet
  // temperature; Ree-Eyring when effects.non_newtonian). A state whose pressure is not of
  // this grid (e.g. empty) gives coefficient NaN and zero tractions.
  FilmFriction Friction(const ContactConditions& c, const FilmState& state) const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

std::string ToString(LineContactSolver::Termination t);

}  // namespace tehl

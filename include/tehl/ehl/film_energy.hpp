// Temperature across and along a lubricant film and on both solid surfaces: the energy
// equation of seed 004 eq. (9) in dimensional form, coupled to the moving-heat-source surface
// temperatures of eqs. (14)-(15) (DESIGN.md sections 4-5; docs/theory.md, "Energy equation and
// surface temperatures"). Gear-free: the flow field comes in as arrays.
//
//   rho cp (dT/dt + u dT/dx + w dT/dz) - d/dz(k(p) dT/dz)
//       = eta (du/dz)^2 - (T/rho)(d rho/dT)(dp/dt + u dp/dx)                       (eq. 9)
//   T(x, z = 0) = T1(x),  T(x, z = h) = T2(x)                        (film and solid touch)
//   T_s(x) = T0 + 1/sqrt(pi rho_s c_s k_s u_s) int_{x_0}^{x} q_s(x')/sqrt(x - x') dx'  (14-15)
//            (or Jaeger's finite-Peclet kernel over the whole grid: Options::finite_peclet)
//   q_1 = +k dT/dz at z = 0, q_2 = -k dT/dz at z = h   (heat flux from the film into solid s)
//   T = T0 where fluid enters the grid (at x_0 when u > 0, at x_{n-1} when u < 0).
//
// rho(p, T) and d rho/dT come from lubricant.density(), k(p) from lubricant.conductivity(), cp
// from lubricant.heat_capacity_j_kgk(); eta (du/dz)^2 is an input (the pressure solver owns the
// viscosity and the velocity profile). The cross-film velocity w is not an input: it follows
// from continuity d(rho)/dt + d(rho u)/dx + d(rho w)/dz = 0, cell by cell.
//
// Discretization (finite volumes on the mapped grid x, xi = z/h, xi_j = j/(nz-1), j = 0 at
// surface 1): vertex-centred cells, half cells at both surfaces and both ends; x-face mass
// fluxes rho u h dxi with the temperature upwinded by the sign of each face flux (reverse flow
// handled as it comes), corrected from the inlet face on by a uniform velocity across the
// film so that every column conserves mass (the given profile need not: its largest correction
// relative to the mass flow is reported as Summary::mass_defect); cross-film mass fluxes from
// per-cell continuity; conduction across the film
// central; heating and compression as cell sources; implicit Euler (BDF1) in time. The heat
// flux into each solid is the residual of the surface half cell's balance, so the energy
// balance closes to round-off. The surface temperatures are unknowns of
// the same sparse system (dense lower-triangular coupling by the moving-heat-source weights),
// solved by KLU, whose block-triangular ordering reduces that coupling to forward substitution
// wherever no fluid flows against x. The temperature dependence of rho, d rho/dT and of the
// compression term is iterated (Picard, optionally relaxed), each step a chord step with the
// latest factorization; the first factorization leaves out the surface history inside
// recirculation zones (which would fill their diagonal blocks), and the iteration falls back
// to the exact factorization when it contracts too slowly (Options::max_chord_steps).
#pragma once

#include <Eigen/Core>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "tehl/ehl/grid.hpp"
#include "tehl/ehl/surface_temperature.hpp"

namespace tehl {

class Lubricant;
namespace internal {
class FilmEnergySystem;
}

// The flow field of a film at one instant, at the n nodes of the grid and the nz cross-film
// nodes xi_j = j/(nz-1) (j = 0 on surface 1, j = nz-1 on surface 2).
struct FilmFlowField {
  Eigen::VectorXd p_pa;          // pressure (negative values are taken as 0) [Pa]
  Eigen::VectorXd h_m;           // film thickness; > 0 [m]
  Eigen::VectorXd dpdt_pa_s;     // dp/dt at fixed x; empty = 0 (steady) [Pa/s]
  Eigen::VectorXd dhdt_m_s;      // dh/dt at fixed x; empty = 0 (steady) [m/s]
  Eigen::MatrixXd u_m_s;         // n x nz: velocity u(x_i, xi_j) along x [m/s]
  Eigen::MatrixXd heating_w_m3;  // n x nz: viscous dissipation eta (du/dz)^2 >= 0 [W/m^3]
  // Optional temperature response of the heating (both empty = heating independent of T):
  // the solve uses heating_w_m3 exp(-heating_decay (T - heating_reference_t)), so that a
  // dissipation computed from eta(T_ref) falls as the film warms (Couette shear at fixed
  // sliding speed: eta (du/h)^2 ~ eta(T) ~ exp(-beta (T - T_ref)), beta = -d ln eta/dT).
  // Linearized about each Picard iterate (a Newton step on this source); where T = T_ref the
  // heating is heating_w_m3 itself, so a coupling that converges T_ref -> T is unaffected.
  Eigen::MatrixXd heating_decay_1_k;      // n x nz: >= 0; empty = 0 [1/K]
  Eigen::MatrixXd heating_reference_t_k;  // n x nz: T_ref; > 0, needed with the decay [K]
  double u1_m_s = 0;                      // speed of surface 1 in +x; > 0 with moving solids [m/s]
  double u2_m_s = 0;                      // speed of surface 2 in +x; > 0 with moving solids [m/s]
};

// The wall heat fluxes of one earlier time level and how far the solids moved during it: what
// the solids remember of it (include/tehl/ehl/surface_temperature.hpp, History).
struct SolidFluxLevel {
  Eigen::VectorXd q1_w_m2;  // heat flux from the film into solid 1 [W/m^2]
  Eigen::VectorXd q2_w_m2;  // heat flux from the film into solid 2 [W/m^2]
  double travel1_m = 0;     // u1 dt of the level [m]; infinite for a steady level
  double travel2_m = 0;     // u2 dt of the level [m]; infinite for a steady level
  double speed1_m_s = 0;    // u1 during the level [m/s]; 0: unknown (taken as the step's)
  double speed2_m_s = 0;    // u2 during the level [m/s]; 0: unknown (taken as the step's)
};

// The most earlier levels a FilmTemperature keeps; shorter steps merge the oldest ones [-].
inline constexpr int kMaxSolidFluxLevels = 256;

// Temperatures and wall heat fluxes: the solution, the previous time level, the initial guess.
struct FilmTemperature {
  Eigen::MatrixXd t_k;            // n x nz film temperature; columns 0, nz-1 = the surfaces [K]
  Eigen::VectorXd t1_k;           // surface temperature of solid 1 (= column 0) [K]
  Eigen::VectorXd t2_k;           // surface temperature of solid 2 (= column nz-1) [K]
  Eigen::VectorXd q1_w_m2;        // heat flux from the film into solid 1 [W/m^2]
  Eigen::VectorXd q2_w_m2;        // heat flux from the film into solid 2 [W/m^2]
  // The solids' heat history (transient steps with moving high-Peclet solids; docs/theory.md,
  // "The solids' heat history"): how far and how fast the surfaces moved during this level
  // (u dt, u), and the earlier levels, newest first, back to one transit of the grid. A steady
  // level has infinite travels and no earlier levels (its flux had always acted), as has a
  // level whose solids are quasi-steady (fixed walls, finite_peclet).
  double travel1_m = std::numeric_limits<double>::infinity();  // [m]
  double travel2_m = std::numeric_limits<double>::infinity();  // [m]
  double speed1_m_s = 0;  // [m/s]; 0: unknown (a state not made by a solve)
  double speed2_m_s = 0;  // [m/s]
  std::vector<SolidFluxLevel> earlier;
  double MaxTemperature() const;  // max over the film [K]
  double MeanTemperature(int i) const;  // cross-film mean at node i (trapezoidal in xi) [K]
  bool Matches(int n, int nz) const;    // every field (the earlier levels' too) fits an n x nz film
};

// Energy budget of the film per unit face width [W/m]; generated = shear + compression.
struct EnergyBalance {
  double shear_w_m = 0;          // integral of eta (du/dz)^2 over the film [W/m]
  double compression_w_m = 0;    // integral of -(T/rho)(drho/dT)(dp/dt + u dp/dx) [W/m]
  double convected_out_w_m = 0;  // net rho cp u (T - T0) flow out through both ends [W/m]
  double into_solid1_w_m = 0;    // integral of q1 dx [W/m]
  double into_solid2_w_m = 0;    // integral of q2 dx [W/m]
  double stored_w_m = 0;         // rate of change of the film's heat content (T - T0) [W/m]
  // |generated - out - solids - stored| / max(|generated|, 1e-300) [-]
  double RelativeError() const;
};

class FilmEnergySolver {
 public:
  enum class Walls {
    kMovingSolids,      // T1, T2 from the moving-heat-source integrals (eqs. 14-15)
    kFixedTemperature,  // T1 = T2 = T0: solids of infinite thermal inertia (analytic limits)
  };
  struct Options {
    int film_nodes = 11;        // nz, cross-film nodes incl. both surfaces [-]; >= 3
    double tolerance_k = 1e-3;  // stop when the estimated remaining error max |T - T_k| < this:
                                // the last change times max(1, r/(1-r)), r its contraction
                                // [K]; > 0
    int max_iterations = 50;    // steps (Picard on rho(T), chord) [-]; >= 1
    double relaxation = 1.0;    // T_k = T_k-1 + relaxation (T_solved - T_k-1), (0, 1] [-]
    Walls walls = Walls::kMovingSolids;
    // Each step is x += relaxation A_f^-1 (b(x) - A(x) x) with A_f a factorization that may be
    // older than A(x) (a chord step) or, first, A without its reverse-flow couplings (block
    // triangular: cheap; Gauss-Seidel on the recirculation). A step whose observed
    // contraction would need more than max_chord_steps further steps to reach tolerance_k is
    // redone with a fresh factorization of the full A. With the far surface history out of
    // the matrix a factorization is cheap: 3 instead of 20 cut the Picard steps of the thermal
    // seed 004 cycle (513 nodes) from 3686 to 2403 and its CPU time by about 6 %, with the
    // same results (docs/performance.md). reuse_factorization: start each Solve from the previous Solve's
    // factorization, as the coupling loop of a pressure solver re-solves a slowly changing
    // flow; false = a fresh factorization (without reverse flow) in every Solve.
    bool reuse_factorization = true;
    // Lags i - k <= this of the surface-temperature history kept in the factorized matrix, the
    // rest applied by FFT and lagged (GMRES steps on the whole history if that converges
    // slowly) [cells].
    int history_near_cells = 4;                 // >= 0 [-]
    // Surface temperatures from Jaeger's moving line source at the solids' own Peclet numbers
    // (include/tehl/ehl/surface_temperature.hpp; effect `finite_peclet`) instead of the
    // high-Peclet form of eqs. (14)-(15). The heat a solid conducts ahead of the film's
    // sources is lagged by the iteration (applied by FFT), like the far history.
    bool finite_peclet = false;
    int max_chord_steps = 3;                    // >= 1 [-]
    std::vector<std::string> Validate() const;  // every violated rule; empty = valid
  };
  enum class Termination { kConverged, kMaxIterations, kLinearSolverFailed };
  struct Summary {
    Termination termination = Termination::kLinearSolverFailed;
    std::string message = "Solve() was not called.";
    int iterations = 0;        // linear solves (Picard / chord steps) [-]
    int factorizations = 0;    // KLU numeric factorizations among them [-]
    int krylov_iterations = 0;  // GMRES iterations of the finite-Peclet steps [-]
    double max_change_k = -1;  // max |T| change of the last iteration (0 for a linear problem) [K]
    double mass_defect = 0;    // largest face-flux correction to continuity / mass flow (a film
                               //   at rest: / its storage rates' terms; 0 when nothing moves) [-]
    EnergyBalance balance;
    double wall_time_s = 0;  // [s]
    bool usable() const { return termination == Termination::kConverged; }
    std::string BriefReport() const;
  };

  // Throws InputError if the options, the solids (with kMovingSolids) or the inlet
  // temperature are invalid. The lubricant must outlive the solver.
  FilmEnergySolver(const UniformGrid& grid,
                   const Lubricant& lubricant,
                   const SolidThermal& solid1,
                   const SolidThermal& solid2,
                   double inlet_temperature_k,
                   const Options& options);

  ~FilmEnergySolver();
  FilmEnergySolver(FilmEnergySolver&&) noexcept;
  FilmEnergySolver& operator=(FilmEnergySolver&&) noexcept;

  const UniformGrid& grid() const { return grid_; }
  const Options& options() const { return options_; }
  double inlet_temperature_k() const { return t0_; }

  // Everything at T0, no heat flux.
  FilmTemperature Initial() const;

  // Steady when dt_s <= 0 (previous ignored); else implicit Euler from `previous` over dt_s.
  // t: the initial guess on entry when it Matches(n, nz) (else Initial()), the solution on
  // exit. Throws InputError on a malformed flow field (sizes, non-finite values, h <= 0,
  // u1 or u2 <= 0 with kMovingSolids) or a missing previous level. A solve that does not
  // converge says so in the Summary and leaves its last iterate in t. Solve keeps the last
  // factorization for the next call: one solver per thread.
  Summary Solve(const FilmFlowField& flow,
                const FilmTemperature* previous,
                double dt_s,
                FilmTemperature* t) const;
  // The same with tolerance_k [K] (> 0) in place of Options::tolerance_k: an outer coupling
  // loop solves loosely while its own iterate still moves by much more (inexact solves).
  Summary Solve(const FilmFlowField& flow,
                const FilmTemperature* previous,
                double dt_s,
                double tolerance_k,
                FilmTemperature* t) const;

 private:
  UniformGrid grid_;
  const Lubricant* lubricant_;
  SolidThermal solid1_, solid2_;
  double t0_;
  Options options_;
  mutable std::unique_ptr<internal::FilmEnergySystem> system_;  // kept factorization
  // Whether a Solve on the kept system_ found the chord steps stalled by the far history (so
  // the later Solves on it take Krylov steps from their first step on).
  mutable bool krylov_steps_ = false;
  // GMRES iterations of the latest Krylov step [-], and the count past which the next step
  // factorizes afresh [-].
  mutable int last_krylov_step_ = 0;
  static constexpr int kKrylovRefresh = 10;
};

std::string ToString(FilmEnergySolver::Termination t);
std::string ToString(FilmEnergySolver::Walls w);

}  // namespace tehl

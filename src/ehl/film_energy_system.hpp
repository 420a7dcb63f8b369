// The linear system of one Picard iteration of the film energy equation (finite volumes on
// the mapped grid, surface temperatures as unknowns) and its KLU solution. Private to
// FilmEnergySolver (include/tehl/ehl/film_energy.hpp; docs/theory.md gives the scheme).
#pragma once

#include <Eigen/Core>
#include <limits>
#include <memory>
#include <vector>

#include "ehl/far_history.hpp"
#include "tehl/ehl/film_energy.hpp"

namespace tehl::internal {

// n x nz per-cell values, row-major: the assembly runs along the film nodes (j) of each grid
// node (i).
using CellMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// What the system needs besides the film: the fixed inputs of one Solve.
struct FilmEnergyInputs {
  const FilmFlowField* flow = nullptr;
  const Eigen::MatrixXd* previous_t_k = nullptr;  // n x nz, transient only
  double dt_s = 0;                                // <= 0: steady
  double cp_j_kgk = 0;                            // lubricant heat capacity [J/(kg K)]
  double t0_k = 0;                                // inlet temperature [K]
  bool fixed_walls = false;                       // T1 = T2 = T0
  double factor1 = 0, factor2 = 0;                // 1/sqrt(pi rho c k u) of solids 1, 2
  // u/(2 kappa) of solids 1, 2 with finite-Peclet surface temperatures, else 0 [1/m]
  double omega1 = 0, omega2 = 0;
  // The solids' heat history (src/ehl/solid_heat_history.hpp): the lags the step's own flux
  // covers (u dt; infinite: all of them) and the earlier levels' part H (null: none)
  // [m, W/m^2 m^(1/2)].
  double reach1_m = std::numeric_limits<double>::infinity();
  double reach2_m = std::numeric_limits<double>::infinity();
  const Eigen::VectorXd* history1 = nullptr;
  const Eigen::VectorXd* history2 = nullptr;
};

// Unknown / equation layout: column block i = [theta_i0 .. theta_i(nz-1), s1_i, s2_i], with
// theta = T - T0 (no round-off from T0 itself: a film without sources solves to exactly 0) and
// s_i = q_i dx (the wall flux scaled to the size of a temperature coefficient).
class FilmEnergySystem {
 public:
  // near_cells: the lags of the moving-heat-source history kept in A (0 <= i - k <= near_cells);
  // the rest enters the residual by FFT and is lagged by the factorization. finite_peclet:
  // Jaeger's kernel (FilmEnergyInputs::omega1, omega2), whose upstream lags i - k < 0 are
  // always lagged (they would join every column into one diagonal block of KLU).
  FilmEnergySystem(const UniformGrid& grid, int nz, int near_cells, bool finite_peclet);
  ~FilmEnergySystem();

  // Assembles A and b with the properties evaluated at t_iter (n x nz): rho, drho/dT,
  // drho/dp at every node and k at every column, evaluated by the caller.
  void Assemble(const FilmEnergyInputs& in,
                const Eigen::MatrixXd& t_iter,
                const CellMatrix& rho,
                const CellMatrix& drho_dt,
                const CellMatrix& drho_dp,
                const Eigen::VectorXd& k_w_mk);
  // Factorizes the assembled A (exact), or A without the moving-heat-source history inside
  // recirculation zones (cheap: banded diagonal blocks; an approximate inverse for the chord
  // iteration). KLU; the symbolic analysis is kept while the pattern stays the same, the
  // numeric one refactored in the old pivot order. False if KLU fails.
  bool Factorize(bool exact);
  bool HasFactorization() const;
  // Whether the last factorization kept the whole surface history of A (true also when A has
  // no reverse flow).
  bool factorized_exact() const { return factorized_exact_; }
  // Whether even the last exact factorization left couplings of A out: the conduction to
  // upstream columns (moving walls) and the history beyond the near band inside recirculation
  // zones. Then every step is a chord step. A is an M-matrix and leaving out upstream
  // conduction a regular splitting of it, so those steps converge, at a rate of about the
  // cell Peclet number's inverse.
  bool lags_couplings() const { return lags_couplings_; }
  // Whether A (assembled) leaves a far history out: then even a factorization of the full A
  // is a chord step, and a step is exact only when this is false.
  bool lags_far_history() const { return moving_walls_ && (!far_[0].empty() || !far_[1].empty()); }
  // delta = A_f^-1 (b - A x) with A_f the last factorized matrix (a chord step), or with
  // krylov (and a far history outside A) the solution of A_whole delta = b - A_whole x by
  // GMRES preconditioned with A_f, to a relative residual kKrylovTolerance. False if KLU fails
  // or delta is not finite.
  bool Correction(const Eigen::VectorXd& x, bool krylov, Eigen::VectorXd* delta) const;
  // x = [theta, s] of a temperature field and back.
  Eigen::VectorXd Pack(const FilmTemperature& t, double t0_k) const;
  void Unpack(const Eigen::VectorXd& x, double t0_k, FilmTemperature* t) const;
  // The energy budget of the assembled system at the temperatures t.
  EnergyBalance Balance(const FilmEnergyInputs& in, const FilmTemperature& t) const;
  double mass_defect() const { return mass_defect_; }
  // GMRES iterations of the finite-Peclet steps so far [-].
  int krylov_iterations() const { return krylov_iterations_; }

 private:
  struct Klu;
  void ComputeMassFluxes(const FilmEnergyInputs& in,
                         const Eigen::MatrixXd& t_iter,
                         const CellMatrix& rho,
                         const CellMatrix& drho_dt,
                         const CellMatrix& drho_dp);
  void BuildMatrix(const FilmEnergyInputs& in);

  int n_, nz_, block_;
  double dx_, dxi_;
  UniformGrid grid_;
  int near_cells_;
  bool finite_peclet_;
  MovingHeatSource source_[2];         // the kernels of solids 1 and 2
  FarHistory far_[2];                  // their far parts (as built into the matrix)
  mutable std::vector<double> far_y_;  // work array of the far history [m^(1/2) m]
  bool moving_walls_ = false;
  bool lags_couplings_ = false;
  // Conduction along x through face i - 1/2 per unit of dxi (0 at the ends) [W/(m K)], and
  // the heat capacity of the assembled system [J/(kg K)].
  std::vector<double> kx_face_;
  double cp_ = 0;
  static constexpr double kZonePeclet = 10.0;  // [-]
  // GMRES of the finite-Peclet steps: restart, iteration budget [-], relative residual [-].
  static constexpr int kKrylovRestart = 30, kKrylovMaxIterations = 150;
  static constexpr double kKrylovTolerance = 3e-2;
  mutable int krylov_iterations_ = 0;
  int built_near_ = -1;  // the near band of the built matrix [cells]
  // Per cell (n x nz): volume, mass, dM/dt, x-face mass flux on the west face (n+1 rows:
  // row i = face i - 1/2), cross-film flux through the north face (from j to j+1).
  CellMatrix volume_, mass_, dmass_dt_, fx_, gz_;
  // Coefficients of row (i, j): aP th_ij + aS th_i(j-1) + aN th_i(j+1) + aW th_(i-1)j
  // + aE th_(i+1)j (+ wall flux) = b, th = T - T0; compression c_ij and whether it was implicit.
  CellMatrix ap_, as_, an_, aw_, ae_, b_, compression_, comp_explicit_t_;
  // Heating g at the iterate heat_t_ and its decay rate: the source g (1 - slope (T - heat_t_)).
  CellMatrix heat_, heat_slope_, heat_t_;
  std::vector<int> col_ptr_, row_idx_;
  std::vector<double> values_, rhs_;
  std::vector<char> signature_;  // upwind pattern and wall model of the built matrix
  double built_factor1_ = 0, built_factor2_ = 0, built_omega1_ = 0, built_omega2_ = 0;
  double built_reach1_ = std::numeric_limits<double>::infinity();
  double built_reach2_ = std::numeric_limits<double>::infinity();
  std::vector<int> fact_ptr_, fact_idx_;  // the factorized matrix (A or an approximation)
  std::vector<double> fact_val_;
  bool factorized_exact_ = false;
  std::vector<int> analyzed_ptr_, analyzed_idx_;
  std::unique_ptr<Klu> klu_;
  double mass_defect_ = 0;
};

}  // namespace tehl::internal

// The linearized Newton system of the line-contact solver, in scaled unknowns
// z = [P_1 .. P_{n-2}, H0] (P = p/p_ref, H0 = h0/h_ref), and the two linear solvers behind
// one interface: dense LU (the reference) and Newton-Krylov (GMRES with FFT Jacobian-vector
// products, preconditioned by a band LU of the Reynolds stencil plus a band of the elastic
// matrix and a coarse-space correction).
//
// Row of interior node i (index i-1), with a row weight c_i < 0 (the complementarity is
// p >= 0, -r >= 0, p r = 0; c_i = -1/|dr_i/dP_i| makes both arguments of the min comparable):
//   cavitated (P_i <= c_i r_i): F = P_i,       dF/dz = e_{i-1}
//   otherwise:                  F = c_i r_i,   dF/dP_j = c_i p_ref (A_ij + sum_k B_ik K_kj),
//                                              dF/dH0  = c_i h_ref sum_k B_ik
// Load row (index m = n-2):    F = (dx sum p - w)/w,  dF/dP_j = dx p_ref / w.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace tehl {
class ElasticDeflection;
}

namespace tehl::internal {

struct NewtonSystem {
  int n = 0;                      // grid nodes; unknowns m + 1 = n - 1
  double dx = 0;                  // [m]
  double p_ref = 1, h_ref = 1;    // unknown scales [Pa], [m]
  const Eigen::VectorXd* row_scale = nullptr;  // c_i < 0 per node [m^2 s/kg]
  double load = 1;                // w [N/m]
  const Eigen::Matrix<double, Eigen::Dynamic, 4>* a = nullptr;  // dr_i/dp_k, k = i-2..i+1
  const Eigen::Matrix<double, Eigen::Dynamic, 4>* b = nullptr;  // dr_i/dh_k
  const ElasticDeflection* elastic = nullptr;                   // null = rigid
  std::vector<char> cavitated;    // per node (size n): row is P_i itself

  int unknowns() const { return n - 1; }
  // y = J x (x, y of size n-1), with the elastic product through the FFT.
  void Apply(const Eigen::VectorXd& x, Eigen::VectorXd* y) const;
  // J as a dense matrix (O(n^2) memory).
  Eigen::MatrixXd Dense() const;
  // d[i] = dr_i/dp_i including the elastic part (node i's own column of A + B K) [1/Pa scaled
  // r], i = 1 .. n-2 (d[0] = d[n-1] = 0).
  void Diagonals(Eigen::VectorXd* d) const;

 private:
  mutable Eigen::VectorXd pv_, hv_;  // Apply's scratch: pressure [Pa] and film change [m]
};

class NewtonLinearSolver {
 public:
  virtual ~NewtonLinearSolver() = default;
  // Solves J dz = rhs for the system's current linearization. Returns false on failure.
  virtual bool Solve(const NewtonSystem& system, const Eigen::VectorXd& rhs,
                     Eigen::VectorXd* dz, std::string* why) = 0;
  virtual int last_krylov_iterations() const { return 0; }
  // Relative tolerance of the next iterative solve (an inexact Newton forcing term); <= 0
  // restores the solver's own setting. Direct solvers ignore it.
  virtual void SetRelativeTolerance(double /*tolerance*/) {}
  virtual std::string Name() const = 0;
};

std::unique_ptr<NewtonLinearSolver> MakeDenseLuSolver();
struct KrylovSettings {
  int restart = 60;
  int max_iterations = 400;
  int band = 24;
  double relative_tolerance = 1e-10;
  // Newton-Krylov: > 0 = the two-level preconditioner with c to 2c coarse pressures (one per
  // 16 cells in between; banded_film_preconditioner.hpp, coarse_correction.hpp); 0 = the
  // hierarchy of strides (film_augmented_preconditioner.hpp).
  int coarse_pressures = 128;
  // Two-level: > 1 = hats this many lattice cells wide before ElasticZoneStart on a lattice of
  // half the stride CoarseStride gives (coarse_correction.hpp); 1 = uniform hats.
  int inlet_hats = 8;
  // Two-level: > 0 = at each Newton system, factorize the band's rows again from n /
  // outlet_refresh nodes before the outlet (or before the first row whose cavitation
  // changed) on; 0 = keep the band as factorized (newton_krylov_solver.cpp).
  int outlet_refresh = 16;
};
std::unique_ptr<NewtonLinearSolver> MakeNewtonKrylovSolver(const KrylovSettings& settings);
// GMRES preconditioned by the dense LU of an earlier Jacobian, refactorized when GMRES needs
// more than settings.max_iterations.
std::unique_ptr<NewtonLinearSolver> MakeReusedLuSolver(const KrylovSettings& settings);

}  // namespace tehl::internal

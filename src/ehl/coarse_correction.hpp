// Coarse-space (two-level) correction of the Newton system (newton_system.hpp): a Galerkin
// projection of the full Jacobian onto piecewise-linear pressures on a coarse grid of stride
// G (nodes G, 2G, ... of the fine grid) plus the rigid approach H0, with the load row kept as
// its own coarse row:
//   Z = [hats | e_H0],  W = [hats | e_load],  E = W^T J Z,  C x = Z E^{-1} W^T x.
// Used with a cheap fine preconditioner M (the one-level band LU of
// banded_film_preconditioner.hpp, whose truncated kernel misses only the smooth, long-range
// part of the elastic coupling) as
//   y = C x;  y += M^{-1} (x - J y)      (coarse first, then the fine solve).
// J Z is formed without FFTs: the deflection of a hat of width 2G centred at node N is the
// hat-smoothed kernel kh(|k - N|) shifted to N, so each column costs O(n) and E O(n n_c).
//
// Wider hats in the inlet (wide_multiple = m > 1): below node `wide_until` only every m-th
// lattice node carries a hat, so the coarse pressures go where the elastic coupling is strong
// (the Hertz zone; ElasticZoneStart). Every such hat is piecewise linear with its kinks on the
// lattice, so it is a combination of the uniform hats, Z = Z_G P, and E = P^T E_G P is the
// exact Galerkin matrix of the merged space (E_G that of the uniform one; P sparse).
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/SparseCore>
#include <vector>

namespace tehl::internal {

struct NewtonSystem;
class BandedFilmPreconditioner;
class CoarseCorrection;

// The two-level preconditioner of the Newton-Krylov solver: y = C x, then y += M^{-1} (x - J y)
// with the fine level M (banded_film_preconditioner.hpp), and y_i = x_i on cavitated rows (J
// is the identity there, so a Newton step leaves those pressures exactly zero). x and y may
// alias; `scratch` holds three work vectors between calls.
struct TwoLevelScratch {
  Eigen::VectorXd x, coarse_y, fine_rhs;
};
void ApplyTwoLevel(const NewtonSystem& system,
                   const CoarseCorrection& coarse,
                   const BandedFilmPreconditioner& fine,
                   const Eigen::VectorXd& x,
                   Eigen::VectorXd* y,
                   TwoLevelScratch* scratch);

// The stride G the Newton-Krylov solver uses on n nodes for coarse_pressures = c > 0: one
// coarse pressure per 16 cells, between c and 2c of them (newton_krylov_solver.cpp gives the
// measurements behind the rule).
int CoarseStride(int n, int coarse_pressures);

// The first node whose Reynolds row couples to the film within a factor 1e-6 of the most
// strongly coupled row (sum |dr/dh| / sum |dr/dp| over the row's stencil; cavitated rows
// skipped): where the elastic part of J starts to matter, about 1.5 Hertz half-widths before
// the centre in the Moes-point films of docs/performance.md. 0 for a rigid system.
int ElasticZoneStart(const NewtonSystem& system);

class CoarseCorrection {
 public:
  // Builds and factorizes E for the system's current linearization; stride >= 2 fine cells
  // per lattice cell, hats wide_multiple lattice cells wide below node wide_until (1: all
  // hats on the lattice). False if the grid is too small for two coarse pressures or E is
  // singular.
  bool Build(const NewtonSystem& system, int stride, int wide_until = 0, int wide_multiple = 1);
  // y = Z E^{-1} W^T x (vectors of the Newton unknowns, size n - 1).
  void Apply(const Eigen::VectorXd& x, Eigen::VectorXd* y) const;
  int coarse_size() const { return static_cast<int>(e_.rows()); }  // nc + 1 [-]
  const Eigen::MatrixXd& matrix() const { return e_; }  // E = W^T J Z

 private:
  bool MergeInlet(int wide_until, int wide_multiple);  // P and E = P^T E_G P; false: uniform
  int n_ = 0, stride_ = 0, nc_ = 0;         // fine nodes, G, uniform hats (lattice nodes)
  bool merged_ = false;                     // E is P^T E_G P (the space has wide inlet hats)
  Eigen::SparseMatrix<double> merge_;       // P extended by the H0 entry: (nc + 1) x (merged + 1)
  mutable Eigen::VectorXd rf_, sf_;         // uniform restriction and prolongation of Apply
  double HatWeight(int node, int c) const;  // hat c (centre (c+1) G) at a fine node
  Eigen::MatrixXd e_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  mutable Eigen::VectorXd rc_;
  std::vector<double> hat_;  // hat weights 1 - t/G, t = 0 .. G - 1
};

}  // namespace tehl::internal

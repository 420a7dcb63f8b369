// Preconditioner of the Newton system (newton_system.hpp) from an augmented sparse system with
// the film change as an extra unknown ("differential deflection": Evans & Hughes, Proc. IMechE
// C 214 (2000); Holmes, Evans & Snidle, ASME J. Tribol. 125 (2003)).
//
// Unknowns (scaled as in NewtonSystem): P_1..P_{n-2}, H_0..H_{n-1} (H = dh/h_ref), H0.
//   Reynolds row i:  cavitated: P_i;  otherwise c_i (p_ref sum_k A_ik P_k + h_ref sum_k B_ik H_k)
//   film rows, on a hierarchy of strides g = 1, r, r^2, ... (r = 16): node k belongs to the
//     highest level whose stride divides it. Top level (<= ~8 nodes, plus k = 0 and n-1):
//     exact dense rows  H_k - H0 - (p_ref/h_ref) sum_j K_|k-j| P_j = 0.
//     Other nodes, level stride g, neighbours l = k - g, r = min(k + g, n - 1), weights
//     w = (1, -(1 + g/(r-k)), g/(r-k)) (a second difference):
//       w_l H_l + w_k H_k + w_r H_r - (p_ref/h_ref) sum_{|k-j| <= band g} D_kj P_j = 0,
//       D_kj = w_l K_|l-j| + w_k K_|k-j| + w_r K_|r-j|,
//     plus the row sum of the dropped tail on the diagonal (exact for uniform P).
//   load row:  (dx p_ref / w) sum_j P_j.
// With untruncated rows the film rows give H = H0 + (p_ref/h_ref) K P exactly (each level's
// chains are Dirichlet problems between nodes of higher levels), so eliminating H reproduces J.
// D decays like g^2/d^2 (second difference of ln|x|), so the band drops only a weak tail; the
// levels carry the smooth part that a single band misses (with one level, stride 1, the
// GMRES iterations grew like sqrt(n): 15, 22, 30, 42, 57 at n = 1025 .. 16385, half-band 8).
// The matrix (2n - 1 unknowns) is factorized by UMFPACK (symmetric strategy); the symbolic
// analysis is kept while n and the band do not change (the pattern does not depend on the
// cavitated set: cavitated Reynolds rows keep their stencil entries as explicit zeros).
// After each factorization the factors P R A Q = L U are taken out of UMFPACK once
// (umfpack_di_get_numeric; R the row scaling) and UMFPACK's Numeric object is freed; Solve
// runs its own substitutions: scale and permute, L by rows (unit diagonal), U by columns,
// permute. The factors are stored as runs of consecutive indices (they come in dense blocks),
// so the solve reads few indices and contiguous stretches of the vector: 1.5-2.3x faster per
// solve than umfpack_di_wsolve at n = 2049 .. 16385, same result to 1e-11 relative; the
// extraction costs ~18 % of a numeric factorization (docs/performance.md).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

namespace tehl::internal {

struct NewtonSystem;

class FilmAugmentedPreconditioner {
 public:
  FilmAugmentedPreconditioner();
  ~FilmAugmentedPreconditioner();
  FilmAugmentedPreconditioner(const FilmAugmentedPreconditioner&) = delete;
  FilmAugmentedPreconditioner& operator=(const FilmAugmentedPreconditioner&) = delete;

  // Assembles and factorizes the augmented matrix of `system` with half-band `band` >= 0 (in
  // strides of the row's level) of the second-differenced kernel. False (with a reason) if the
  // factorization fails.
  bool Factorize(const NewtonSystem& system, int band, std::string* why);
  // y ~ J^{-1} x for vectors of size n - 1 (the Newton unknowns).
  void Solve(const Eigen::VectorXd& x, Eigen::VectorXd* y) const;
  int symbolic_analyses() const { return symbolic_analyses_; }  // [-]

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int symbolic_analyses_ = 0;
};

}  // namespace tehl::internal

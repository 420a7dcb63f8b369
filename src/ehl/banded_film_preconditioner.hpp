// One-level augmented preconditioner of the Newton system (newton_system.hpp), factorized as a
// bordered band matrix. The same "differential deflection" rows as
// film_augmented_preconditioner.hpp with a single level of stride 1:
//   Reynolds row i:  cavitated: P_i;  otherwise c_i (p_ref sum_k A_ik P_k + h_ref sum_k B_ik H_k)
//   film row k = 1 .. n-2:  H_{k-1} - 2 H_k + H_{k+1} - (p_ref/h_ref) sum_{|k-j| <= band} D_kj P_j
//                           (D the second-differenced kernel, the dropped tail's row sum on the
//                           diagonal)
//   border rows:  H_0 - H0 - (p_ref/h_ref) sum_j K_j P_j,  H_{n-1} - H0 - ...,  the load row.
// In the node order (H_k, P_k), k = 1 .. n-2, the core is a band matrix (half-bands
// max(4, 2 band) below and max(3, 2 band) above) bordered by three rows (the two exact film
// rows, the load row) and three columns (H_0, H_{n-1}, H0). The core is factorized by the
// band LU with interchanges inside node pairs (pair_pivoted_band_lu.hpp), or by LAPACK's
// banded LU with partial pivoting (dgbtrf) when a pivot of the former falls below the
// threshold, and the border by its 3 x 3 Schur complement: O(n band^2) to factorize and
// O(n band) to solve, with no fill beyond the band. What the truncated kernel misses is
// smooth and long-ranged: coarse_correction.hpp supplies it.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "ehl/pair_pivoted_band_lu.hpp"

namespace tehl::internal {

struct NewtonSystem;

class BandedFilmPreconditioner {
 public:
  // Assembles and factorizes the bordered band matrix of `system` with kernel half-band
  // `band` >= 1. False (with a reason) if the band LU or the Schur complement is singular.
  bool Factorize(const NewtonSystem& system, int band, std::string* why);
  // After a successful Factorize with pair interchanges (paired()): the Reynolds rows of
  // nodes first_node .. n - 2 from `system`, the rows before them as they were, the core
  // eliminated again only from about first_node on (PairPivotedBandLu::RefactorizeFrom). Where
  // the Jacobian drifts between Newton iterations (the outlet: the pressure spike and the
  // cavitation boundary), this gives nearly a fresh factorization's GMRES counts at a fraction
  // of its cost (docs/performance.md). False (with a reason if the border is singular) if it
  // cannot: the caller factorizes again.
  bool Refresh(const NewtonSystem& system, int first_node, std::string* why);
  // y ~ J^{-1} x for vectors of size n - 1 (the Newton unknowns).
  void Solve(const Eigen::VectorXd& x, Eigen::VectorXd* y) const;
  // The core's LU first tries interchanges within node pairs (pair_pivoted_band_lu.hpp) and
  // falls back on LAPACK's dgbtrf when a pivot is below `t` times its column's largest entry
  // below it; t < 0: dgbtrf only. Default 0.1.
  void set_pair_pivot_threshold(double t) { pair_threshold_ = t; }
  bool paired() const { return paired_; }  // the last factorization pivoted within pairs

 private:
  void Substitute(double* b) const;  // b <- (core)^{-1} b with the LU factors in ab_
  void MeasureFactors();
  template <typename Add>
  void Assemble(const NewtonSystem& system, int first_node, Add&& add);
  bool FinishBorder(std::string* why);
  int n_ = 0, size_ = 0, kl_ = 0, ku_ = 0, ldab_ = 0;  // core size 2 (n - 2)
  int band_ = 0;
  std::vector<double> kc_, d2_, film_diag_;  // (p_ref/h_ref) K_q; its second difference in
                                             // the band; each film row's P_i entry (negated)
  Eigen::MatrixXd bc_;                       // border columns H_0, H_{n-1}, H0 of the core rows
  double pair_threshold_ = 0.1;
  PairPivotedBandLu pair_;     // the core's LU with interchanges inside node pairs ...
  bool paired_ = false;        // ... if its pivots held; otherwise LAPACK's:
  std::vector<double> ab_;     // LAPACK band storage of the core, then its LU factors
  std::vector<int> ipiv_;
  // The factors packed column by column for the substitution (MeasureFactors): for column j,
  // its L multipliers up to the last nonzero one (l_len_[j] <= kl), then U's entries above
  // the diagonal from the first nonzero one (u_len_[j] <= kl + ku; about ku where dgbtrf did
  // not pivot), starting at offset_[j]; and the reciprocal of U(j, j).
  std::vector<double> packed_, inv_diag_;
  std::vector<int> u_len_, l_len_;
  std::vector<std::size_t> offset_;
  Eigen::MatrixXd y_;          // C^{-1} B_c (size_ x 3)
  Eigen::MatrixXd yp_;         // its P rows (n - 2 x 3)
  Eigen::MatrixXd border_;     // B_r restricted to the P columns (3 x (n - 2))
  Eigen::Matrix3d schur_inv_;  // (D - B_r C^{-1} B_c)^{-1}
  mutable Eigen::VectorXd work_, up_;
};

}  // namespace tehl::internal

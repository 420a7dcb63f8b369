// The far part of the moving-heat-source history (include/tehl/ehl/surface_temperature.hpp)
// applied by FFT. The history sum_k G_ik s_k is a convolution on the uniform grid (G_ik
// depends only on i - k for the interior cells 1 <= k <= n - 2; the half cells at both ends
// have their own weights), causal in the high-Peclet form. The film energy system keeps its
// near part, 0 <= i - k <= near_cells, as sparse matrix entries and needs the rest, the far
// part
//   y_i = sum_{k : i - k > near_cells or i - k < 0} G_ik s_k,
// in its residual: O(n log n) by a zero-padded real FFT instead of O(n^2) sums. In the
// finite-Peclet form the far part includes every upstream lag i - k < 0.
// Private to the film energy system (src/ehl/film_energy_system.hpp).
#pragma once

#include <complex>
#include <memory>
#include <vector>

#include "tehl/ehl/surface_temperature.hpp"

namespace tehl::internal {

class FarHistory {
 public:
  // near_cells >= 0: the lags kept out of the far part. Builds the FFTW plans (under the
  // process-wide planner lock) and the kernel's spectrum.
  FarHistory(const MovingHeatSource& source, int near_cells);
  // Another kernel of the same grid size (a solid at another speed, another near band): the
  // plans are kept, the spectrum recomputed. Throws std::invalid_argument on another size.
  void Reset(const MovingHeatSource& source, int near_cells);
  ~FarHistory();
  FarHistory(const FarHistory&) = delete;
  FarHistory& operator=(const FarHistory&) = delete;

  int size() const { return n_; }
  int near_cells() const { return near_; }
  int fft_size() const { return m_; }
  // True when the far part is identically zero (high-Peclet form, n - 1 <= near_cells).
  bool empty() const { return empty_; }
  // y_i (i = 0..n-1) for s_k = s[k * stride] [unit of s times m^(1/2)]. Uses the object's
  // buffers: one FarHistory per thread.
  void Apply(const double* s, int stride, double* y) const;
  // The same by the direct O(n^2) sum (the reference of the tests).
  void ApplyDirect(const double* s, int stride, double* y) const;

 private:
  struct Plans;
  int n_ = 0, near_ = 0, m_ = 0;
  bool empty_ = true;
  std::vector<double> inlet_;                     // G_i0 where far, else 0 [m^(1/2)]
  std::vector<double> outlet_;                    // G_i(n-1) where far, else 0 [m^(1/2)]
  std::vector<std::complex<double>> kernel_hat_;  // spectrum of the far kernel / m
  MovingHeatSource source_;
  std::unique_ptr<Plans> plans_;  // null until a kernel needs them
};

}  // namespace tehl::internal

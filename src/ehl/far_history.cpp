// FFT of the far moving-heat-source history (src/ehl/far_history.hpp).
#include "ehl/far_history.hpp"

#include <fftw3.h>

#include <algorithm>
#include <memory>
#include <mutex>
#include <new>
#include <stdexcept>
#include <utility>

#include "ehl/fftw_planner.hpp"

namespace tehl::internal {

struct FarHistory::Plans {
  double* real = nullptr;            // m values
  fftw_complex* spectrum = nullptr;  // m/2 + 1 values
  fftw_plan forward = nullptr, backward = nullptr;
  ~Plans() {
    {
      std::lock_guard<std::mutex> lock(FftwPlannerMutex());
      if (forward) fftw_destroy_plan(forward);
      if (backward) fftw_destroy_plan(backward);
    }
    fftw_free(real);
    fftw_free(spectrum);
  }
};

FarHistory::FarHistory(const MovingHeatSource& source, int near_cells)
    : n_(source.size()), near_(std::max(near_cells, 0)), source_(source) {
  inlet_.assign(n_, 0.0);
  for (int i = near_ + 1; i < n_; ++i) inlet_[i] = source.Weight(i, 0);
  if (empty()) return;
  // Lags that occur for k >= 1: i - k in [near + 1, n - 2]. A circular convolution of length m
  // reproduces the linear one at i < n when the wrapped lags (m + i - k >= m - n + 2 for k > i)
  // miss the kernel's support (<= n - 2): m >= 2n - 3. Powers of two for FFTW.
  m_ = 2;
  while (m_ < 2 * n_ - 3) m_ *= 2;
  const int mc = m_ / 2 + 1;
  auto plans = std::make_unique<Plans>();
  plans->real = static_cast<double*>(fftw_malloc(sizeof(double) * m_));
  plans->spectrum = static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * mc));
  if (!plans->real || !plans->spectrum) throw std::bad_alloc();
  {
    std::lock_guard<std::mutex> lock(FftwPlannerMutex());
    plans->forward = fftw_plan_dft_r2c_1d(m_, plans->real, plans->spectrum, FFTW_ESTIMATE);
    plans->backward = fftw_plan_dft_c2r_1d(m_, plans->spectrum, plans->real, FFTW_ESTIMATE);
  }
  if (!plans->forward || !plans->backward) throw std::runtime_error("FFTW could not build a plan");
  // Far kernel: G at lag l = Weight(l + 1, 1) for near < l <= n - 2, zero elsewhere.
  std::fill(plans->real, plans->real + m_, 0.0);
  for (int lag = near_ + 1; lag <= n_ - 2; ++lag) plans->real[lag] = source.Weight(lag + 1, 1);
  fftw_execute(plans->forward);
  kernel_hat_.resize(mc);
  const double inv_m = 1.0 / m_;  // the backward transform is unnormalized
  for (int q = 0; q < mc; ++q)
    kernel_hat_[q] = std::complex<double>(plans->spectrum[q][0], plans->spectrum[q][1]) * inv_m;
  plans_ = std::move(plans);
}

FarHistory::~FarHistory() = default;

void FarHistory::Apply(const double* s, int stride, double* y) const {
  if (empty()) {
    std::fill(y, y + n_, 0.0);
    return;
  }
  Plans& p = *plans_;
  p.real[0] = 0.0;  // the inlet cell has its own weights, added below
  for (int k = 1; k < n_; ++k) p.real[k] = s[static_cast<long>(k) * stride];
  std::fill(p.real + n_, p.real + m_, 0.0);
  fftw_execute(p.forward);
  for (int q = 0; q < m_ / 2 + 1; ++q) {
    const std::complex<double> r =
        std::complex<double>(p.spectrum[q][0], p.spectrum[q][1]) * kernel_hat_[q];
    p.spectrum[q][0] = r.real();
    p.spectrum[q][1] = r.imag();
  }
  fftw_execute(p.backward);
  for (int i = 0; i < n_; ++i) y[i] = p.real[i] + inlet_[i] * s[0];
  // Lags <= near are zero in the kernel; the round-off of the transforms is not: exact zeros
  // where the far part is empty.
  std::fill(y, y + std::min(near_ + 1, n_), 0.0);
}

void FarHistory::ApplyDirect(const double* s, int stride, double* y) const {
  for (int i = 0; i < n_; ++i) {
    double sum = 0;
    for (int k = 0; k < i - near_; ++k)
      sum += source_.Weight(i, k) * s[static_cast<long>(k) * stride];
    y[i] = sum;
  }
}

}  // namespace tehl::internal

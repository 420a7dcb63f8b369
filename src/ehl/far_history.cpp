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
#include "ehl/spectrum_product.hpp"

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

FarHistory::FarHistory(const MovingHeatSource& source, int near_cells) : n_(source.size()) {
  Reset(source, near_cells);
}

void FarHistory::Reset(const MovingHeatSource& source, int near_cells) {
  if (source.size() != n_) throw std::invalid_argument("FarHistory::Reset: another grid size");
  near_ = std::max(near_cells, 0);
  source_ = source;
  auto far = [&](int i, int k) { return i - k > near_ || i - k < 0; };
  inlet_.assign(n_, 0.0);
  outlet_.assign(n_, 0.0);
  empty_ = true;
  for (int i = 0; i < n_; ++i) {
    if (far(i, 0)) inlet_[i] = source.Weight(i, 0);
    if (n_ > 1 && far(i, n_ - 1)) outlet_[i] = source.Weight(i, n_ - 1);
    empty_ = empty_ && inlet_[i] == 0 && outlet_[i] == 0;
  }
  // The interior cells 1 <= k <= n - 2 seen from the nodes 0 <= i <= n - 1: lags i - k in
  // [-(n - 2), n - 2]. A circular convolution of length m reproduces the linear one when these
  // 2n - 3 lags stay distinct modulo m: m >= 2n - 3. Powers of two for FFTW.
  std::vector<double> kernel(2 * n_ - 1, 0.0);  // at n - 1 + lag
  for (int lag = -(n_ - 2); lag <= n_ - 2; ++lag)
    if (lag > near_ || lag < 0) {
      const int k = lag >= 0 ? 1 : n_ - 2;  // an interior cell with i = k + lag on the grid
      kernel[n_ - 1 + lag] = source.Weight(k + lag, k);
      empty_ = empty_ && kernel[n_ - 1 + lag] == 0;
    }
  if (empty_) return;
  if (!plans_) {
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
    if (!plans->forward || !plans->backward)
      throw std::runtime_error("FFTW could not build a plan");
    plans_ = std::move(plans);
  }
  Plans& p = *plans_;
  std::fill(p.real, p.real + m_, 0.0);
  for (int lag = -(n_ - 2); lag <= n_ - 2; ++lag) p.real[(lag + m_) % m_] = kernel[n_ - 1 + lag];
  fftw_execute(p.forward);
  const int mc = m_ / 2 + 1;
  kernel_hat_.resize(mc);
  const double inv_m = 1.0 / m_;  // the backward transform is unnormalized
  for (int q = 0; q < mc; ++q)
    kernel_hat_[q] = std::complex<double>(p.spectrum[q][0], p.spectrum[q][1]) * inv_m;
}

FarHistory::~FarHistory() = default;

void FarHistory::Apply(const double* s, int stride, double* y) const {
  if (empty()) {
    std::fill(y, y + n_, 0.0);
    return;
  }
  Plans& p = *plans_;
  // The end cells have their own weights, added below.
  std::fill(p.real, p.real + m_, 0.0);
  for (int k = 1; k < n_ - 1; ++k) p.real[k] = s[static_cast<long>(k) * stride];
  fftw_execute(p.forward);
  MultiplySpectrum(p.spectrum, kernel_hat_.data(), m_ / 2 + 1);
  fftw_execute(p.backward);
  const double s_last = s[static_cast<long>(n_ - 1) * stride];
  for (int i = 0; i < n_; ++i) y[i] = p.real[i] + inlet_[i] * s[0] + outlet_[i] * s_last;
  // In the high-Peclet form lags <= near are zero in the kernel; the round-off of the
  // transforms is not: exact zeros where the far part is empty.
  if (source_.high_peclet()) std::fill(y, y + std::min(near_ + 1, n_), 0.0);
}

void FarHistory::ApplyDirect(const double* s, int stride, double* y) const {
  for (int i = 0; i < n_; ++i) {
    double sum = 0;
    for (int k = 0; k < n_; ++k)
      if (i - k > near_ || i - k < 0)
        sum += source_.Weight(i, k) * s[static_cast<long>(k) * stride];
    y[i] = sum;
  }
}

}  // namespace tehl::internal

#include "tehl/ehl/elastic_deflection.hpp"

#include <fftw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "ehl/fftw_planner.hpp"
#include "ehl/fftw_wisdom.hpp"
#include "ehl/spectrum_product.hpp"
#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl {

namespace internal {

std::mutex& FftwPlannerMutex() {
  static std::mutex mutex;
  return mutex;
}

double LogCellIntegral(int k) {
  if (k < 0) k = -k;
  if (k == 0) return std::log(0.5) - 1.0;  // 2 G(1/2)
  // G(k+1/2) - G(k-1/2) = k ln((k+1/2)/(k-1/2)) + (1/2) ln((k+1/2)(k-1/2)) - 1; the first
  // term written with log1p so that it stays accurate when k is large (it tends to 1).
  const double kd = static_cast<double>(k);
  return kd * std::log1p(1.0 / (kd - 0.5)) + 0.5 * std::log((kd + 0.5) * (kd - 0.5)) - 1.0;
}

namespace {

// Padded FFT length: the smallest EVEN m >= target of the form 2^a 3^b 5^c 7^d with d <= 1.
// Measured with FFTW 3.3 r2c + c2r (bench/elastic_bench.cpp, and a size sweep): odd lengths
// and high powers of 7 are 2-3 times slower (n = 16385: 32805 = 3^8 5 takes 505 us, 33600 =
// 2^6 3 5^2 7 takes 160 us); a power of two wastes up to 2x in length.
int SmoothSize(int target) {
  if (target <= 2) return std::max(target, 1);
  for (int m = target + (target % 2);; m += 2) {
    int r = m;
    for (int f : {2, 3, 5}) {
      while (r % f == 0) r /= f;
    }
    if (r % 7 == 0) r /= 7;
    if (r == 1) return m;
  }
}

}  // namespace
}  // namespace internal

struct ElasticDeflection::Impl {
  int n = 0;
  int m = 0;  // padded FFT length
  double dx_m = 0;
  double e_prime_pa = 0;
  std::vector<double> coefficients;              // K_k, k = 0..n-1 [m/Pa]
  std::vector<std::complex<double>> kernel_hat;  // DFT of the wrapped kernel, / m
  double* real_buffer = nullptr;                 // m values
  fftw_complex* spectrum = nullptr;              // m/2 + 1 values
  fftw_plan forward = nullptr;
  fftw_plan backward = nullptr;

  ~Impl() {
    {
      std::lock_guard<std::mutex> lock(internal::FftwPlannerMutex());
      if (forward) fftw_destroy_plan(forward);
      if (backward) fftw_destroy_plan(backward);
    }
    fftw_free(real_buffer);
    fftw_free(spectrum);
  }
};

ElasticDeflection::ElasticDeflection(int n, double dx_m, double e_prime_pa, FftPlanEffort effort) {
  ProblemList problems;
  auto rule = [&](bool ok, const char* key, double value, const char* what, const char* allowed) {
    if (ok) return;
    std::ostringstream v;
    v << value;
    problems.Add({"", 0, std::string("ElasticDeflection::") + key, v.str(), what, allowed});
  };
  rule(n >= 1, "n", n, "must be >= 1", "a grid of at least one point");
  rule(dx_m > 0 && std::isfinite(dx_m), "dx_m", dx_m, "must be > 0 [m]", "a positive spacing");
  rule(e_prime_pa > 0 && std::isfinite(e_prime_pa), "e_prime_pa", e_prime_pa, "must be > 0 [Pa]",
       "a positive reduced modulus");
  problems.ThrowIfAny();

  impl_ = std::make_unique<Impl>();
  Impl& d = *impl_;
  d.n = n;
  d.dx_m = dx_m;
  d.e_prime_pa = e_prime_pa;
  d.m = internal::SmoothSize(2 * n - 1);

  // K_k = -(4/(pi E')) dx (ln dx + I_k): the cell integral of ln|s| scaled to unit cells.
  const double scale = -4.0 / (kPi * e_prime_pa) * dx_m;
  const double log_dx = std::log(dx_m);
  d.coefficients.resize(n);
  for (int k = 0; k < n; ++k) {
    d.coefficients[k] = scale * (log_dx + internal::LogCellIntegral(k));
  }

  const int m = d.m;
  const int mc = m / 2 + 1;
  d.real_buffer = static_cast<double*>(fftw_malloc(sizeof(double) * m));
  d.spectrum = static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * mc));
  if (!d.real_buffer || !d.spectrum) throw std::bad_alloc();
  {
    // FFTW_MEASURE overwrites the buffers while planning: plan before filling them.
    const bool measure = effort == FftPlanEffort::kMeasure;
    const unsigned flags = measure ? FFTW_MEASURE : FFTW_ESTIMATE;
    std::lock_guard<std::mutex> lock(internal::FftwPlannerMutex());
    if (measure) internal::ImportWisdomOnce();  // TEHL_FFTW_WISDOM (fftw_wisdom.hpp)
    const auto start = std::chrono::steady_clock::now();
    d.forward = fftw_plan_dft_r2c_1d(m, d.real_buffer, d.spectrum, flags);
    d.backward = fftw_plan_dft_c2r_1d(m, d.spectrum, d.real_buffer, flags);
    // A plan taken from wisdom is built in microseconds to a few milliseconds; a longer
    // planning measured new plans, worth keeping.
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (measure && seconds > 0.02 && d.forward && d.backward) {
      const std::string file = internal::WisdomFile();
      if (!file.empty()) internal::ExportWisdom(file);
    }
  }
  if (!d.forward || !d.backward) throw std::runtime_error("FFTW could not build a plan");

  // Wrapped kernel for a linear convolution of length-n sequences on m >= 2n - 1 points:
  // index k holds K_k, index m - k holds K_k (negative lags), the rest is zero padding.
  std::fill(d.real_buffer, d.real_buffer + m, 0.0);
  for (int k = 0; k < n; ++k) d.real_buffer[k] = d.coefficients[k];
  for (int k = 1; k < n; ++k) d.real_buffer[m - k] = d.coefficients[k];
  fftw_execute(d.forward);
  d.kernel_hat.resize(mc);
  const double inv_m = 1.0 / m;  // FFTW's backward transform is unnormalized
  for (int q = 0; q < mc; ++q) {
    d.kernel_hat[q] = std::complex<double>(d.spectrum[q][0], d.spectrum[q][1]) * inv_m;
  }
}

ElasticDeflection::~ElasticDeflection() = default;
ElasticDeflection::ElasticDeflection(ElasticDeflection&&) noexcept = default;
ElasticDeflection& ElasticDeflection::operator=(ElasticDeflection&&) noexcept = default;

int ElasticDeflection::size() const { return impl_->n; }
double ElasticDeflection::dx_m() const { return impl_->dx_m; }
double ElasticDeflection::e_prime_pa() const { return impl_->e_prime_pa; }
int ElasticDeflection::fft_size() const { return impl_->m; }

double ElasticDeflection::Coefficient(int k) const {
  TEHL_ASSERT(k >= 0 && k < impl_->n, "Coefficient index out of range");
  return impl_->coefficients[k];
}

void ElasticDeflection::Apply(const double* p_pa, double* v_m) const {
  Impl& d = *impl_;
  std::copy(p_pa, p_pa + d.n, d.real_buffer);
  std::fill(d.real_buffer + d.n, d.real_buffer + d.m, 0.0);
  fftw_execute(d.forward);
  internal::MultiplySpectrum(d.spectrum, d.kernel_hat.data(), d.m / 2 + 1);
  fftw_execute(d.backward);
  std::copy(d.real_buffer, d.real_buffer + d.n, v_m);
}

Eigen::VectorXd ElasticDeflection::Apply(const Eigen::VectorXd& p_pa) const {
  TEHL_ASSERT(p_pa.size() == impl_->n, "Apply: size mismatch");
  Eigen::VectorXd v(impl_->n);
  Apply(p_pa.data(), v.data());
  return v;
}

void ElasticDeflection::ApplyDirect(const double* p_pa, double* v_m) const {
  const Impl& d = *impl_;
  std::vector<double> v(d.n, 0.0);  // p and v may alias
  for (int i = 0; i < d.n; ++i) {
    double sum = 0.0;
    for (int j = 0; j < d.n; ++j) sum += d.coefficients[std::abs(i - j)] * p_pa[j];
    v[i] = sum;
  }
  std::copy(v.begin(), v.end(), v_m);
}

Eigen::MatrixXd ElasticDeflection::DenseMatrix() const {
  const Impl& d = *impl_;
  Eigen::MatrixXd k(d.n, d.n);
  for (int j = 0; j < d.n; ++j) {
    for (int i = 0; i < d.n; ++i) k(i, j) = d.coefficients[std::abs(i - j)];
  }
  return k;
}

}  // namespace tehl

// Elastic deflection of a line contact by discrete convolution (DESIGN.md sections 4-5).
//
// Continuous form (DESIGN.md section 4, Dowson-Higginson E', 2/E' = (1-nu1^2)/E1 + (1-nu2^2)/E2):
//   v(x) = -(4/(pi E')) int p(x') ln|x - x'| dx'     (+ a constant, absorbed in h0).
// A positive pressure gives a positive v: the surfaces are pushed apart, the film grows.
//
// Discrete form on a uniform grid x_i = x_0 + i dx, i = 0..n-1, with the pressure piecewise
// constant on the cells [x_j - dx/2, x_j + dx/2]:
//   v_i = sum_j K_|i-j| p_j,
//   K_k = -(4/(pi E')) int_{k dx - dx/2}^{k dx + dx/2} ln|s| ds
//       = -(4/(pi E')) [F(k dx + dx/2) - F(k dx - dx/2)],  F(s) = s ln|s| - s, F(0) = 0.
// The coefficients are exact for piecewise-constant pressure (no quadrature error); the
// matrix K is symmetric Toeplitz. Apply() evaluates the sum in O(n log n) by a zero-padded
// (linear, not circular) FFT convolution (Liu, Wang & Liu, Wear 243 (2000), DC-FFT), with the
// kernel transform and the FFTW plans built once in the constructor.
//
// The additive constant of v depends on the length unit (ln|s| in metres); callers absorb it
// in the rigid approach h0, so only differences of v carry physics.
#pragma once

#include <Eigen/Core>
#include <memory>

namespace tehl {

// How much effort FFTW spends choosing its algorithm when the plans are built. Measured with
// bench/elastic_bench.cpp (FFTW 3.3, 2-core x86-64, CPU time):
//  - kMeasure (default): Apply() is 10-40% faster than with kEstimate (n = 2049: 18 vs 26 us;
//    n = 16385: 182 vs 254 us), but the FIRST plan of a size in a process costs 0.1 s
//    (n = 513) to several seconds (n = 16385). Later objects of that size reuse FFTW's
//    in-process wisdom and are built in 0.05-2 ms. Best for a solver that evaluates the
//    deflection 1e5+ times on one grid (Newton-Krylov over a mesh cycle).
//  - kEstimate: heuristic plan, built in 0.1-2 ms; deterministic (kMeasure picks algorithms by
//    timing, so the last bits of v may differ between runs). Best for one-off evaluations,
//    tests and the dry-contact solver.
enum class FftPlanEffort { kMeasure, kEstimate };

class ElasticDeflection {
 public:
  // n >= 1 grid points [-], dx_m > 0 grid spacing [m], e_prime_pa > 0 reduced modulus E' [Pa].
  // Throws InputError for values outside those ranges. Builds K, its transform and the FFTW
  // plans (plan creation is serialized by a process-wide mutex, so objects may be built and
  // destroyed on different threads concurrently).
  ElasticDeflection(int n,
                    double dx_m,
                    double e_prime_pa,
                    FftPlanEffort effort = FftPlanEffort::kMeasure);
  ~ElasticDeflection();
  ElasticDeflection(ElasticDeflection&&) noexcept;
  ElasticDeflection& operator=(ElasticDeflection&&) noexcept;
  ElasticDeflection(const ElasticDeflection&) = delete;
  ElasticDeflection& operator=(const ElasticDeflection&) = delete;
  // A moved-from object may only be destroyed or assigned to.

  int size() const;           // n [-]
  double dx_m() const;        // grid spacing [m]
  double e_prime_pa() const;  // reduced modulus E' [Pa]
  // Padded FFT length used by Apply() (>= 2n - 1; even, 2^a 3^b 5^c 7^{0 or 1}) [-].
  int fft_size() const;

  // K_k for k = 0..n-1 [m/Pa]: deflection at x_i per unit pressure on cell i +- k.
  double Coefficient(int k) const;

  // v = K p in O(n log n). p_pa and v_m point to n values [Pa], [m]; they may alias.
  // Reuses the object's plans and work buffers: NOT thread-safe. Use one object per thread
  // (building one is cheap once FFTW has wisdom for the size). Accuracy: max|v - K p| is a
  // few 1e-16 of max|v| for non-negative p (see elastic_deflection_test.cpp).
  void Apply(const double* p_pa, double* v_m) const;
  Eigen::VectorXd Apply(const Eigen::VectorXd& p_pa) const;

  // v = K p by the O(n^2) double sum: the reference for Apply(). Thread-safe.
  void ApplyDirect(const double* p_pa, double* v_m) const;

  // K as a dense n x n symmetric Toeplitz matrix, entry (i, j) = K_|i-j| [m/Pa].
  Eigen::MatrixXd DenseMatrix() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

namespace internal {
// Exact integral of ln|s| over a cell of width dx centred at k dx, divided by dx, minus ln dx:
//   I_k = (1/dx) int_{k dx - dx/2}^{k dx + dx/2} ln|s| ds - ln(dx)
//       = G(k + 1/2) - G(k - 1/2),  G(t) = t ln|t| - t,
// evaluated without cancellation for large k. Dimensionless [-].
double LogCellIntegral(int k);
}  // namespace internal

}  // namespace tehl

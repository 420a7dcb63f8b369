// The pieces of one GMRES iteration of the Newton-Krylov solver at n nodes, on the random
// Newton system of tests/support/random_newton_system.hpp (real steel kernel, random
// order-one stencils, the last fifth of the rows cavitated): the band LU substitution of the
// fine level (both factorization paths), the coarse correction, one Jacobian product (FFT +
// stencil) and one FFT convolution alone. Each reported as a time and in FFT convolutions of
// the same n (`per_fft`), so that the ratios come from one process. docs/performance.md uses
// them.
#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <string>

#include "ehl/banded_film_preconditioner.hpp"
#include "ehl/coarse_correction.hpp"
#include "ehl/newton_system.hpp"
#include "support/random_newton_system.hpp"

namespace {

// Times one FFT convolution v = K p of the system's kernel (FFTW_MEASURE plans, as the solver
// makes them) [s].
double FftSeconds(const tehl::testing::RandomNewtonSystem& rs) {
  const int n = rs.sys.n;
  Eigen::VectorXd p = Eigen::VectorXd::Ones(n), v(n);
  const int reps = std::max(200, 2000000 / n);
  const auto c0 = std::chrono::steady_clock::now();
  for (int r = 0; r < reps; ++r) {
    rs.kernel.Apply(p.data(), v.data());
    benchmark::DoNotOptimize(v.data());
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count() / reps;
}

template <class Body>
void Measure(benchmark::State& state, const tehl::testing::RandomNewtonSystem& rs, Body body) {
  const double fft_s = FftSeconds(rs);
  long calls = 0;
  const auto c0 = std::chrono::steady_clock::now();
  for (auto _ : state) {
    body();
    ++calls;
  }
  const double s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count() / calls;
  state.counters["fft_us"] = 1e6 * fft_s;
  state.counters["us"] = 1e6 * s;
  state.counters["per_fft"] = s / fft_s;
}

// The fine level's factorization path from the second argument: 1 = interchanges within
// node pairs (threshold 0, so that the random system takes it: the EHL systems take it at the
// default threshold), 0 = LAPACK's dgbtrf. Reported as `paired`.
tehl::internal::BandedFilmPreconditioner FinePreconditioner(const benchmark::State& state) {
  tehl::internal::BandedFilmPreconditioner pre;
  pre.set_pair_pivot_threshold(state.range(1) == 1 ? 0.0 : -1.0);
  return pre;
}

// Fine level: one substitution with the band LU (half-band 8, the default).
void BM_BandSolve(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  tehl::testing::RandomNewtonSystem rs(n, 3, tehl::FftPlanEffort::kMeasure);
  tehl::internal::BandedFilmPreconditioner pre = FinePreconditioner(state);
  std::string why;
  if (!pre.Factorize(rs.sys, 8, &why)) state.SkipWithError(why.c_str());
  const Eigen::VectorXd x = rs.RandomVector();
  Eigen::VectorXd y;
  Measure(state, rs, [&] {
    pre.Solve(x, &y);
    benchmark::DoNotOptimize(y.data());
  });
  state.counters["paired"] = pre.paired();
}

// Fine level: the whole factorization (assembly, band LU, rearranging the factors, the
// border's Schur complement).
void BM_BandFactorize(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  tehl::testing::RandomNewtonSystem rs(n, 3, tehl::FftPlanEffort::kMeasure);
  tehl::internal::BandedFilmPreconditioner pre = FinePreconditioner(state);
  std::string why;
  Measure(state, rs, [&] { benchmark::DoNotOptimize(pre.Factorize(rs.sys, 8, &why)); });
  state.counters["paired"] = pre.paired();
}

// Coarse level: y = Z E^{-1} W^T x with about 128 coarse pressures.
void BM_CoarseApply(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  tehl::testing::RandomNewtonSystem rs(n, 3, tehl::FftPlanEffort::kMeasure);
  tehl::internal::CoarseCorrection cc;
  if (!cc.Build(rs.sys, std::max(2, (n - 1) / 129))) state.SkipWithError("coarse build");
  const Eigen::VectorXd x = rs.RandomVector();
  Eigen::VectorXd y;
  Measure(state, rs, [&] {
    cc.Apply(x, &y);
    benchmark::DoNotOptimize(y.data());
  });
}

// Coarse level: building E = W^T J Z and its LU, at the solver's stride (CoarseStride with
// its default of 128 to 256 coarse pressures). Paid at every refactorization, with the fine
// level's.
void BM_CoarseBuild(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  tehl::testing::RandomNewtonSystem rs(n, 3, tehl::FftPlanEffort::kMeasure);
  tehl::internal::CoarseCorrection cc;
  const int stride = tehl::internal::CoarseStride(n, 128);
  Measure(state, rs, [&] { benchmark::DoNotOptimize(cc.Build(rs.sys, stride)); });
  state.counters["coarse"] = cc.coarse_size();
}

// One Jacobian product J x (FFT convolution + Reynolds stencil).
void BM_JacobianProduct(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  tehl::testing::RandomNewtonSystem rs(n, 3, tehl::FftPlanEffort::kMeasure);
  const Eigen::VectorXd x = rs.RandomVector();
  Eigen::VectorXd y;
  Measure(state, rs, [&] {
    rs.sys.Apply(x, &y);
    benchmark::DoNotOptimize(y.data());
  });
}

void Sizes(benchmark::internal::Benchmark* b) {
  for (int n = 513; n <= 16385; n = 2 * n - 1) b->Arg(n);
}

void SizesAndPaths(benchmark::internal::Benchmark* b) {
  for (int n = 513; n <= 16385; n = 2 * n - 1) b->Args({n, 0})->Args({n, 1});
}

BENCHMARK(BM_BandSolve)->Apply(SizesAndPaths)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BandFactorize)->Apply(SizesAndPaths)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CoarseApply)->Apply(Sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CoarseBuild)->Apply(Sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_JacobianProduct)->Apply(Sizes)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();

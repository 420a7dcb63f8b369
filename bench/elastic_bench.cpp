// Cost of the elastic deflection v = K p: FFT convolution (Apply) vs the O(n^2) sum
// (ApplyDirect), and the cost of building the FFTW plans with each planner effort.
//   ./elastic_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "tehl/ehl/elastic_deflection.hpp"

namespace {

constexpr double kEPrime = 226.4e9;  // steel-steel E' [Pa]

std::vector<double> Pressure(int n) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> dist(0.0, 2e9);
  std::vector<double> p(n);
  for (double& v : p) v = dist(gen);
  return p;
}

tehl::FftPlanEffort Effort(int64_t code) {
  return code == 0 ? tehl::FftPlanEffort::kMeasure : tehl::FftPlanEffort::kEstimate;
}

// First construction of a size in the process (no wisdom yet): one iteration only. Registered
// first so that it runs before the other benchmarks have planned the same sizes.
void BM_FirstConstruction(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) {
    tehl::ElasticDeflection k(n, 1e-6, kEPrime, Effort(state.range(1)));
    benchmark::DoNotOptimize(k.Coefficient(0));
  }
}

// Construction once FFTW has wisdom for the size (what a study's second solver pays).
void BM_Construction(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) {
    tehl::ElasticDeflection k(n, 1e-6, kEPrime, Effort(state.range(1)));
    benchmark::DoNotOptimize(k.Coefficient(0));
  }
}

void BM_Apply(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const tehl::ElasticDeflection k(n, 1e-6, kEPrime, Effort(state.range(1)));
  const std::vector<double> p = Pressure(n);
  std::vector<double> v(n);
  for (auto _ : state) {
    k.Apply(p.data(), v.data());
    benchmark::DoNotOptimize(v.data());
  }
  state.counters["fft_size"] = k.fft_size();
}

void BM_ApplyDirect(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const tehl::ElasticDeflection k(n, 1e-6, kEPrime, tehl::FftPlanEffort::kEstimate);
  const std::vector<double> p = Pressure(n);
  std::vector<double> v(n);
  for (auto _ : state) {
    k.ApplyDirect(p.data(), v.data());
    benchmark::DoNotOptimize(v.data());
  }
}

// Second argument: 0 = FFTW_MEASURE, 1 = FFTW_ESTIMATE.
void Sizes(benchmark::internal::Benchmark* b, bool both_efforts, int max_n) {
  for (int n = 513; n <= max_n; n = 2 * n - 1) {
    b->Args({n, 0});
    if (both_efforts) b->Args({n, 1});
  }
}

BENCHMARK(BM_FirstConstruction)->Apply([](auto* b) {
                                 Sizes(b, true, 16385);
                               }) -> Iterations(1) -> Unit(benchmark::kMillisecond);
BENCHMARK(BM_Construction)
    ->Apply([](auto* b) { Sizes(b, true, 16385); }) -> Unit(benchmark::kMillisecond);
BENCHMARK(BM_Apply)->Apply([](auto* b) { Sizes(b, true, 16385); }) -> Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ApplyDirect)
    ->Apply([](auto* b) {
      for (int n = 513; n <= 4097; n = 2 * n - 1) b->Args({n});
    }) -> Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();

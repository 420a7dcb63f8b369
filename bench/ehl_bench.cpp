// Cost of the isothermal EHL line-contact solver (docs/performance.md): steady solves at the
// Moes point M = 20, L = 10 with the reference oil (VALIDATION.md section 3), per grid size and
// linear solver, cold (no guess: grid sequencing inside SolveSteady) and warm (re-solve from
// the converged state after the load grew by 1 %, what a mesh cycle mostly does); the one-off
// cost of the elastic-deflection FFT plans; one FFT convolution for the ratio
// (one Newton iteration) / (one FFT convolution); and warm re-solves in a loop (BM_WarmNewton),
// which time many Newton iterations and an FFT convolution in the same process.
//   ./ehl_bench --benchmark_counters_tabular=true
// Every solve is expensive (up to a minute for dense LU at n = 4097), so each BM_Steady runs
// exactly one iteration.
//
// Peak memory: before the solve the kernel's peak-RSS mark is reset to the current RSS by
// writing "5" to /proc/self/clear_refs (Linux >= 4.0); after it, VmHWM - VmRSS(before) from
// /proc/self/status is the extra resident memory the solve needed at its peak (the solver
// object built before the reset is not included). Where clear_refs is not writable the counter
// is -1.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <string>

#include "support/test_lubricants.hpp"
#include "tehl/ehl/elastic_deflection.hpp"
#include "tehl/ehl/line_contact_solver.hpp"
#include "tehl/units.hpp"

namespace {

using Clock = std::chrono::steady_clock;

constexpr double kEPrime = 226.4e9;  // steel-steel E' [Pa]
constexpr double kRadius = 0.01;     // R [m]
constexpr double kEta0 = 0.04;       // reference oil eta0 [Pa s] (VALIDATION.md section 3)
constexpr double kMoesM = 20.0, kMoesL = 10.0;

// Moes M = W (2U)^-1/2, L = G (2U)^1/4 with U = eta0 um/(E' R), W = w/(E' R), G = alpha E'
// (Moes 1992; alpha = Houpert's Roelands-equivalent of the reference oil, Z = 0.68).
tehl::ContactConditions MoesPoint() {
  const double alpha = 0.68 * (std::log(kEta0) + 9.67) / 1.96e8;
  const double g = alpha * kEPrime;
  const double u = std::pow(kMoesL / g, 4) / 2.0;
  const double w = kMoesM * std::sqrt(2.0 * u);
  const double um = u * kEPrime * kRadius / kEta0;
  return tehl::ContactConditions{kRadius, um, um, w * kEPrime * kRadius,
                                 tehl::testing::kReferenceT0};
}

tehl::UniformGrid Grid(int n) {
  const auto hz = tehl::LineContactHertz(MoesPoint().load_n_per_m, kRadius, kEPrime);
  return tehl::UniformGrid::AroundHertz(hz.half_width_m, n);
}

double StatusKb(const char* key) {
  std::ifstream f("/proc/self/status");
  std::string line;
  const std::string k = std::string(key) + ":";
  while (std::getline(f, line))
    if (line.rfind(k, 0) == 0) return std::stod(line.substr(k.size()));
  return -1;
}

bool ResetPeak() {
  std::ofstream f("/proc/self/clear_refs");
  f << "5";
  f.flush();
  return static_cast<bool>(f);
}

double Seconds(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// One-off: building an ElasticDeflection (FFTW_MEASURE plans) for a size the process has not
// planned yet. Registered first, before any solver has planned these sizes.
void BM_DeflectionPlanning(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) {
    tehl::ElasticDeflection k(n, Grid(n).dx_m(), kEPrime, tehl::FftPlanEffort::kMeasure);
    benchmark::DoNotOptimize(k.Coefficient(0));
  }
}

// One FFT convolution v = K p (plans reused), the unit of the Newton-iteration ratio.
void BM_FftConvolution(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const tehl::ElasticDeflection k(n, Grid(n).dx_m(), kEPrime, tehl::FftPlanEffort::kMeasure);
  Eigen::VectorXd p = Eigen::VectorXd::Constant(n, 1e9), v(n);
  for (auto _ : state) {
    k.Apply(p.data(), v.data());
    benchmark::DoNotOptimize(v.data());
  }
}

// Second argument: 0 = auto, 1 = dense LU, 2 = Newton-Krylov, 3 = reused dense LU,
// 4 = Newton-Krylov with the UMFPACK hierarchy, 5 = Newton-Krylov with uniform coarse hats,
// 6 = Newton-Krylov without the outlet refresh of the band
// (SolverOptions).
tehl::LinearSolverKind Kind(int64_t code) {
  switch (code) {
    case 1:
      return tehl::LinearSolverKind::kDense;
    case 2:
    case 4:
    case 5:
    case 6:
      return tehl::LinearSolverKind::kNewtonKrylov;
    case 3:
      return tehl::LinearSolverKind::kReusedLu;
    default:
      return tehl::LinearSolverKind::kAuto;
  }
}

// Solver options for the second benchmark argument (4 = Newton-Krylov with the UMFPACK
// hierarchy instead of the two-level preconditioner).
tehl::LineContactSolver::Options SolverOptions(int64_t code) {
  tehl::LineContactSolver::Options opt;
  opt.linear_solver = Kind(code);
  if (code == 4) opt.preconditioner_coarse_pressures = 0;
  if (code == 5) opt.preconditioner_inlet_hats = 1;  // two-level with uniform coarse hats
  if (code == 6) opt.preconditioner_outlet_refresh = 0;  // the band kept as factorized
  // A failing iterative solve is reported by the counters instead of spending minutes in
  // load continuation.
  if (opt.linear_solver != tehl::LinearSolverKind::kDense) opt.max_continuation_stages = 0;
  return opt;
}

tehl::FilmEffects SteadyEffects() {
  tehl::FilmEffects effects;
  effects.transient = false;
  return effects;
}

// Cold solve then warm re-solve; the benchmark's own time is their sum, the counters split it.
void BM_Steady(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const tehl::Lubricant oil = tehl::testing::ReferenceOil(kEta0, 0.68);
  const tehl::FilmEffects effects = SteadyEffects();
  const tehl::LineContactSolver::Options opt = SolverOptions(state.range(1));
  const tehl::UniformGrid grid = Grid(n);
  const tehl::ContactConditions c = MoesPoint();
  {
    // Untimed: a first solve plans FFTW for this size and for every grid of the sequencing
    // (n/2, n/4, ... 129), so that `cold` measures the solve and not the one-off planning
    // (reported by BM_DeflectionPlanning). The timed solver below is a fresh object.
    tehl::LineContactSolver first(grid, kEPrime, oil, effects, opt);
    tehl::FilmState s;
    first.SolveSteady(c, &s);
  }
  tehl::LineContactSolver solver(grid, kEPrime, oil, effects, opt);
  tehl::ContactConditions c_warm = c;
  c_warm.load_n_per_m *= 1.01;
  for (auto _ : state) {
    const double rss0 = StatusKb("VmRSS");
    const bool peak_ok = ResetPeak();
    tehl::FilmState s;
    auto t0 = Clock::now();
    const auto cold = solver.SolveSteady(c, &s);
    const double cold_s = Seconds(t0);
    t0 = Clock::now();
    const auto warm = solver.SolveSteady(c_warm, &s);
    const double warm_s = Seconds(t0);
    state.counters["peak_mb"] = peak_ok ? (StatusKb("VmHWM") - rss0) / 1024.0 : -1.0;
    state.counters["cold_s"] = cold_s;
    state.counters["cold_ok"] = cold.usable();
    state.counters["cold_newton"] = cold.total_iterations;
    state.counters["cold_gmres"] = cold.krylov_iterations;
    state.counters["warm_s"] = warm_s;
    state.counters["warm_ok"] = warm.usable();
    state.counters["warm_newton"] = warm.total_iterations;
    state.counters["warm_gmres"] = warm.krylov_iterations;
    state.counters["s_per_newton"] =
        warm.total_iterations > 0 ? warm_s / warm.total_iterations : 0.0;
    state.counters["nk"] = warm.linear_solver == "newton_krylov";
  }
}

// Warm re-solves in a loop (what a mesh cycle mostly does): the load alternates between w and
// 1.01 w, each solve starting from the last film. Reports the wall time per Newton iteration
// and its ratio to one FFT convolution of the same n timed in the same process just before
// (`newton_per_fft`; docs/performance.md gives the target, <= 20), plus the GMRES iterations
// per Newton iteration. Second argument: 2 = two-level (default), 4 = the UMFPACK hierarchy.
void BM_WarmNewton(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const tehl::Lubricant oil = tehl::testing::ReferenceOil(kEta0, 0.68);
  const tehl::FilmEffects effects = SteadyEffects();
  const tehl::LineContactSolver::Options opt = SolverOptions(state.range(1));
  const tehl::UniformGrid grid = Grid(n);
  tehl::LineContactSolver solver(grid, kEPrime, oil, effects, opt);
  tehl::ContactConditions c = MoesPoint();
  const double w = c.load_n_per_m;
  tehl::FilmState s;
  solver.SolveSteady(c, &s);
  // One FFT convolution, timed here so that the ratio comes from one run.
  const tehl::ElasticDeflection k(n, grid.dx_m(), kEPrime, tehl::FftPlanEffort::kMeasure);
  Eigen::VectorXd p = s.p_pa, v(n);
  const int fft_reps = std::max(200, 2000000 / n);
  auto t0 = Clock::now();
  for (int r = 0; r < fft_reps; ++r) {
    k.Apply(p.data(), v.data());
    benchmark::DoNotOptimize(v.data());
  }
  const double fft_s = Seconds(t0) / fft_reps;
  long newton = 0, gmres = 0, solves = 0, failed = 0;
  double solve_s = 0;
  for (auto _ : state) {
    c.load_n_per_m = (solves % 2 == 0) ? 1.01 * w : w;
    t0 = Clock::now();
    const auto sum = solver.SolveSteady(c, &s);
    solve_s += Seconds(t0);
    newton += sum.total_iterations;
    gmres += sum.krylov_iterations;
    failed += !sum.usable();
    ++solves;
  }
  state.counters["fft_us"] = 1e6 * fft_s;
  state.counters["newton_per_solve"] = static_cast<double>(newton) / solves;
  state.counters["gmres_per_newton"] = static_cast<double>(gmres) / std::max(1L, newton);
  state.counters["s_per_newton"] = solve_s / std::max(1L, newton);
  state.counters["newton_per_fft"] = solve_s / std::max(1L, newton) / fft_s;
  state.counters["failed"] = static_cast<double>(failed);
}

// Warm re-solves along a monotone sequence, as in a mesh cycle: each solve starts from the
// last film with the load 1 % higher (third argument 0) or the speed 2 % higher (1) than the
// one before. Same counters as BM_WarmNewton; the per-solve time is the benchmark's own.
void BM_WarmSequence(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const tehl::Lubricant oil = tehl::testing::ReferenceOil(kEta0, 0.68);
  const tehl::LineContactSolver::Options opt = SolverOptions(state.range(1));
  const tehl::UniformGrid grid = Grid(n);
  tehl::LineContactSolver solver(grid, kEPrime, oil, SteadyEffects(), opt);
  const tehl::ContactConditions start = MoesPoint();
  tehl::ContactConditions c = start;
  tehl::FilmState s;
  solver.SolveSteady(c, &s);
  long newton = 0, gmres = 0, solves = 0, failed = 0;
  for (auto _ : state) {
    ++solves;
    if (state.range(2) == 0) {
      c.load_n_per_m = start.load_n_per_m * (1.0 + 0.01 * solves);
    } else {
      c.u1_m_s = c.u2_m_s = start.u1_m_s * (1.0 + 0.02 * solves);
    }
    const auto sum = solver.SolveSteady(c, &s);
    newton += sum.total_iterations;
    gmres += sum.krylov_iterations;
    failed += !sum.usable();
  }
  state.counters["newton_per_solve"] = static_cast<double>(newton) / solves;
  state.counters["gmres_per_newton"] = static_cast<double>(gmres) / std::max(1L, newton);
  state.counters["failed"] = static_cast<double>(failed);
}

// One evaluation of the film and the scaled residual with its linearization at a converged
// state (what each Newton iteration pays at least once), in FFT convolutions of the same n
// timed in the same process (`residual_per_fft`).
void BM_Residual(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const tehl::Lubricant oil = tehl::testing::ReferenceOil(kEta0, 0.68);
  const tehl::UniformGrid grid = Grid(n);
  tehl::LineContactSolver solver(grid, kEPrime, oil, SteadyEffects(), SolverOptions(2));
  const tehl::ContactConditions c = MoesPoint();
  tehl::FilmState s;
  solver.SolveSteady(c, &s);
  const tehl::ElasticDeflection k(n, grid.dx_m(), kEPrime, tehl::FftPlanEffort::kMeasure);
  Eigen::VectorXd v(n);
  const int fft_reps = std::max(200, 2000000 / n);
  auto t0 = Clock::now();
  for (int r = 0; r < fft_reps; ++r) {
    k.Apply(s.p_pa.data(), v.data());
    benchmark::DoNotOptimize(v.data());
  }
  const double fft_s = Seconds(t0) / fft_reps;
  long evaluations = 0;
  t0 = Clock::now();
  for (auto _ : state) {
    benchmark::DoNotOptimize(solver.ResidualNorm(c, s));
    ++evaluations;
  }
  state.counters["fft_us"] = 1e6 * fft_s;
  state.counters["residual_per_fft"] = Seconds(t0) / std::max(1L, evaluations) / fft_s;
}

void Sizes(benchmark::internal::Benchmark* b) {
  for (int n = 513; n <= 16385; n = 2 * n - 1) b->Arg(n);
}

void Solves(benchmark::internal::Benchmark* b) {
  for (int n = 513; n <= 16385; n = 2 * n - 1) {
    if (n <= 4097) b->Args({n, 1});  // dense LU: O(n^2) memory, O(n^3) time
    if (n <= 4097) b->Args({n, 3});  // reused dense LU: one O(n^3) factorization or more
    b->Args({n, 2});
    b->Args({n, 4});
    b->Args({n, 5});
    b->Args({n, 6});
  }
}

BENCHMARK(BM_DeflectionPlanning)->Apply(Sizes)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FftConvolution)->Apply(Sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Residual)->Apply(Sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Steady)->Apply(Solves)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_WarmSequence)
    ->ArgsProduct({{1025, 2049, 4097, 8193, 16385}, {2, 5, 6}, {0, 1}})
    ->Iterations(20)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WarmNewton)
    ->ArgsProduct({{513, 1025, 2049, 4097, 8193, 16385}, {2, 4, 5, 6}})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

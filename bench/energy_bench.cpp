// Cost of one steady solve of the film energy equation with moving-solid surface temperatures
// (FilmEnergySolver, docs/theory.md "Energy equation and surface temperatures"), on the
// EHL-like field of the energy tests (Hertzian pressure, b = 0.1 mm, p_H = 0.5 GPa, h_c = 0.5
// um, u1 = 1, u2 = 1.5 m/s, reverse flow in the inlet), SAE 40-like oil (beta = 6.5e-4 1/K),
// bronze solids. Cold = from T0 with a fresh KLU analysis and factorization
// (reuse_factorization = false); warm = from the converged temperature and the kept
// factorization after the heating grew by 1 % (what the thermal coupling loop of the pressure
// solver does). Third argument 1: finite-Peclet surface temperatures (Options::finite_peclet,
// Jaeger's kernel; Pe = u b / (2 kappa) = 2.7 and 4.0 for the two bronze surfaces here),
// against 0, the high-Peclet form, in the same run.
//   ./energy_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <algorithm>

#include "unit/ehl/film_flow_fields.hpp"

namespace {

using tehl::FilmEnergySolver;
using tehl::FilmTemperature;

void Run(benchmark::State& state, bool warm) {
  const int n = static_cast<int>(state.range(0)), nz = static_cast<int>(state.range(1));
  const tehl::Lubricant oil = tehl::testing::EnergyTestOil();
  const tehl::UniformGrid g = tehl::UniformGrid::AroundHertz(1e-4, n);
  const tehl::FilmFlowField field =
      tehl::testing::EhlLikeField(g, nz, oil, tehl::testing::EhlLikeParameters{});
  tehl::FilmFlowField hotter = field;
  hotter.heating_w_m3 *= 1.01;
  FilmEnergySolver::Options o;
  o.film_nodes = nz;
  o.reuse_factorization = warm;
  o.finite_peclet = state.range(2) != 0;
  const FilmEnergySolver solver(g, oil, tehl::testing::Bronze(), tehl::testing::Bronze(),
                                oil.reference_temperature_k(), o);
  FilmTemperature converged;
  solver.Solve(field, nullptr, 0.0, &converged);
  FilmEnergySolver::Summary s;
  for (auto _ : state) {
    FilmTemperature t = warm ? converged : FilmTemperature{};
    s = solver.Solve(warm ? hotter : field, nullptr, 0.0, &t);
    benchmark::DoNotOptimize(t.t_k.data());
  }
  state.counters["iterations"] = s.iterations;
  state.counters["factorizations"] = s.factorizations;
  state.counters["gmres"] = s.krylov_iterations;
  state.counters["balance_error"] = s.balance.RelativeError();
  state.counters["converged"] = s.usable();
}

void BM_EnergySteadyCold(benchmark::State& state) { Run(state, false); }
void BM_EnergySteadyWarm(benchmark::State& state) { Run(state, true); }

// Re-solves on a kept system with polymer-like solids under a 0.1 um film (testing::
// ThinEhlFilm: the surface history lagged outside the factorized matrix makes the chord steps
// diverge), the heating alternating between 1.00 and 1.01 times the film's, as the thermal
// coupling loop re-solves a film that moves a little. Counters per Solve.
void BM_EnergyResolveStronglyCoupled(benchmark::State& state) {
  const tehl::testing::ThinEhlFilm film;
  tehl::FilmFlowField hotter = film.f;
  hotter.heating_w_m3 *= 1.01;
  FilmEnergySolver::Options o;
  o.film_nodes = 11;
  const FilmEnergySolver solver(film.g, film.oil, tehl::testing::Polymer(),
                                tehl::testing::Polymer(), film.oil.reference_temperature_k(), o);
  FilmTemperature t;
  solver.Solve(film.f, nullptr, 0.0, &t);  // finds the stall
  long solves = 0, steps = 0, factorizations = 0, gmres = 0;
  for (auto _ : state) {
    const auto s = solver.Solve(solves % 2 ? film.f : hotter, nullptr, 0.0, &t);
    benchmark::DoNotOptimize(t.t_k.data());
    ++solves;
    steps += s.iterations;
    factorizations += s.factorizations;
    gmres += s.krylov_iterations;
  }
  const double per = 1.0 / std::max(1L, solves);
  state.counters["steps"] = steps * per;
  state.counters["factorizations"] = factorizations * per;
  state.counters["gmres"] = gmres * per;
}

BENCHMARK(BM_EnergyResolveStronglyCoupled)->Unit(benchmark::kMillisecond);

BENCHMARK(BM_EnergySteadyCold)
    ->Args({129, 11, 0})
    ->Args({257, 11, 0})
    ->Args({513, 11, 0})
    ->Args({513, 11, 1})
    ->Args({1025, 11, 0})
    ->Args({1025, 11, 1})
    ->Args({513, 21, 0})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EnergySteadyWarm)
    ->Args({513, 11, 0})
    ->Args({513, 11, 1})
    ->Args({1025, 11, 0})
    ->Args({1025, 11, 1})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

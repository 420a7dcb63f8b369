// The coupling of an isothermal Ree-Eyring film (effect non_newtonian without thermal): one
// steady solve of a sliding steel disc from its cold start, with the Anderson step on log f
// (the default) and with the relaxed step (Options::eyring_anderson = false), in one run so
// that the ratio is measured on one machine state. Disc: R1 = R2 = 20 mm (R = 10 mm), E' =
// 226.4 GPa, w = 355.2 kN/m (p_H = 1.13 GPa), u1 = 3, u2 = 1 m/s, SAE 40 of seed 004
// (tau0 = 5 MPa), without and with a limiting shear stress 1 MPa + 0.05 p.
//   ./eyring_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>
#include <string>

#include "tehl/ehl/grid.hpp"
#include "tehl/ehl/line_contact_solver.hpp"
#include "tehl/lubricant/lubricant.hpp"
#include "tehl/units.hpp"

namespace {

tehl::Lubricant Sae40(bool limit) {
  std::ifstream in(std::string(TEHL_SOURCE_DIR) + "/lubricants/sae40.toml");
  std::stringstream text;
  text << in.rdbuf();
  if (limit) text << "\nlimiting_stress_pa = 1e6\nlimiting_stress_slope = 0.05\n";
  return tehl::Lubricant::FromString(text.str(), "sae40");
}

// range(0): nodes; range(1): 1 = Anderson, 0 = relaxed; range(2): 1 = limiting stress.
void BM_EyringDiscSteady(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const tehl::Lubricant oil = Sae40(state.range(2) != 0);
  constexpr double kEPrime = 226.4e9, kRadius = 0.01, kLoad = 3.552e5;
  const double b = tehl::LineContactHertz(kLoad, kRadius, kEPrime).half_width_m;
  tehl::FilmEffects e;
  e.transient = false;
  e.non_newtonian = true;
  tehl::LineContactSolver::Options o;
  o.eyring_anderson = state.range(1) != 0;
  tehl::LineContactSolver solver(tehl::UniformGrid::AroundHertz(b, n), kEPrime, oil, e, o);
  const tehl::ContactConditions c{kRadius, 3.0, 1.0, kLoad, oil.reference_temperature_k()};
  tehl::LineContactSolver::Summary s;
  for (auto _ : state) {
    tehl::FilmState st;
    s = solver.SolveSteady(c, &st);
    benchmark::DoNotOptimize(st.p_pa.data());
  }
  state.counters["coupling"] = s.coupling_iterations;
  state.counters["newton"] = s.total_iterations;
  state.counters["converged"] = s.usable();
}

}  // namespace

BENCHMARK(BM_EyringDiscSteady)
    ->ArgsProduct({{513, 1025}, {1, 0}, {0, 1}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();

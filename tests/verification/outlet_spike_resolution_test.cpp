// The outlet spike of a real film: its width in x converges under refinement while its width
// in cells grows with the grid, and a rigid film has none.
#include <gtest/gtest.h>

#include "tehl/ehl/outlet_spike.hpp"
#include "thermal_disc_case.hpp"

namespace tehl {
namespace {

using testing::DiscSolver;
using testing::Sae40;
using testing::ThermalDisc;

OutletSpike SpikeOf(const LineContactSolver& solver, const FilmState& s) {
  return FindOutletSpike(s.p_pa, solver.grid().x_start_m(), solver.grid().dx_m());
}

// The 0.8 GPa steel disc of docs/thermal.md ("Open points"), isothermal, L_T = 1. A spike of
// converged shape spans twice the cells on each doubling of the grid; an under-resolved one
// is as narrow as the grid allows (a few cells whatever the grid).
TEST(OutletSpikeResolution, SpikeWidthConvergesInXAndGrowsInCells) {
  ThermalDisc d;
  d.um_m_s = testing::SpeedForLoading(Sae40(), 1.0);
  double width_m_prev = 0, cells_prev = 0;
  for (int n : {1025, 2049, 4097}) {
    LineContactSolver solver = DiscSolver(d, Sae40(), n, false);
    FilmState s;
    ASSERT_TRUE(solver.SolveSteady(d.Conditions(Sae40()), &s).usable()) << n;
    const OutletSpike spike = SpikeOf(solver, s);
    ASSERT_TRUE(spike.found) << n;
    const double b = d.half_width_m();
    EXPECT_GT(spike.x_m, 0.5 * b) << n;  // past the centre, before the outlet
    EXPECT_LT(spike.x_m, b) << n;
    EXPECT_GT(spike.prominence_pa, 0.1 * spike.pressure_pa) << n;
    const double width_m = spike.width_cells * solver.grid().dx_m();
    std::printf("n %d: spike %.4f GPa at x/b %.4f, %.2f cells at half prominence (%.5f b)\n", n,
                spike.pressure_pa * 1e-9, spike.x_m / b, spike.width_cells, width_m / b);
    if (cells_prev > 0) {
      EXPECT_GT(spike.width_cells, 1.6 * cells_prev) << n;
      EXPECT_NEAR(width_m / width_m_prev, 1.0, 0.25) << n;
    }
    EXPECT_FALSE(spike.resolved()) << n;  // < 20 cells up to 4097 nodes on this disc
    width_m_prev = width_m;
    cells_prev = spike.width_cells;
  }
}

// Rigid surfaces (Martin's film): the pressure rises and falls once, no spike.
TEST(OutletSpikeResolution, RigidFilmHasNoSpike) {
  ThermalDisc d;
  d.um_m_s = 1.0;
  d.hertz_pa = 0.1e9;
  FilmEffects e;
  e.transient = false;
  e.elastic = false;
  e.piezoviscous = false;
  LineContactSolver solver(UniformGrid::AroundHertz(d.half_width_m(), 513), d.e_prime_pa, Sae40(),
                           e, LineContactSolver::Options{});
  FilmState s;
  ASSERT_TRUE(solver.SolveSteady(d.Conditions(Sae40()), &s).usable());
  EXPECT_FALSE(SpikeOf(solver, s).found);
}

}  // namespace
}  // namespace tehl

// Thermal reduction of the central film against Gupta et al. 1992 (VALIDATION.md section 4):
//   phi_T = [1 + 0.1 (1 + 14.8 SRR^0.83) L_T^0.64]^-1,  L_T = beta eta0 um^2 / k_f,
// expected: h_c(thermal) / h_c(isothermal) within +-15 % of phi_T for L_T 0.1-5 and SRR 0-1
// (a trend check, not an exact law). Steel twin disc of thermal_disc_case.hpp (R = 20 mm,
// p_H = 0.8 GPa, SAE 40 of seed 004 Table 2: beta = gamma = 0.046 1/K, eta0 = 0.1140574 Pa s,
// k_f = 0.125 W/(m K)); um sets L_T. Newtonian, steady, 257 nodes, 11 across the film.
// The fast binary runs the rolling points up to L_T = 3; the slow one (TEHL_SLOW_TESTS) the
// whole table of docs/validation.md (bench/thermal_gupta_table.cpp prints it).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tehl/lubricant/lubricant.hpp"
#include "verification/thermal_disc_case.hpp"

namespace tehl {
namespace {

using testing::DiscSolver;
using testing::Sae40;
using testing::GuptaFactor;
using testing::ThermalDisc;

TEST(ThermalGupta, ThermalLoadingOfSae40) {
  // L_T per (m/s)^2 from the Table 2 data of lubricants/sae40.toml, by hand:
  // 0.046 x 0.1140574 / 0.125 = 0.041973 s^2/m^2.
  EXPECT_NEAR(testing::ViscosityTemperatureCoefficient(Sae40()), 0.046, 1e-9);
  EXPECT_NEAR(testing::ThermalLoading(Sae40(), 1.0), 0.046 * 0.1140574 / 0.125, 1e-9);
  // phi_T at L_T = 1, SRR = 1: 1 / (1 + 0.1 x 15.8) = 0.387597 (the formula by hand).
  EXPECT_NEAR(GuptaFactor(1.0, 1.0), 1.0 / 2.58, 1e-12);
}

// The isothermal and thermal central films at (L_T, SRR); ratio / phi_T - 1.
double Deviation(double l_t, double srr) {
  ThermalDisc d;
  d.um_m_s = testing::SpeedForLoading(Sae40(), l_t);
  d.srr = srr;
  const ContactConditions c = d.Conditions(Sae40());
  LineContactSolver iso = DiscSolver(d, Sae40(), 257, false);
  LineContactSolver th = DiscSolver(d, Sae40(), 257, true);
  FilmState si, st;
  const auto isum = iso.SolveSteady(c, &si);
  const auto tsum = th.SolveSteady(c, &st);
  EXPECT_TRUE(isum.usable()) << isum.BriefReport();
  EXPECT_TRUE(tsum.usable()) << tsum.BriefReport();
  if (!isum.usable() || !tsum.usable()) return std::nan("");
  const double ratio = st.CentralFilm(th.grid()) / si.CentralFilm(iso.grid());
  const double phi = GuptaFactor(l_t, srr);
  std::printf(
      "L_T %.1f (um %.3f m/s) SRR %.2f: h_c %.4f / %.4f um, ratio %.3f, phi_T %.3f "
      "(%+.1f %%), dT_max %.1f K, %d coupling iterations\n",
      l_t, d.um_m_s, srr, st.CentralFilm(th.grid()) * 1e6, si.CentralFilm(iso.grid()) * 1e6, ratio,
      phi, 100 * (ratio / phi - 1), st.temperature.MaxTemperature() - c.temperature_k,
      tsum.coupling_iterations);
  return ratio / phi - 1.0;
}

// Rolling (SRR = 0) up to L_T = 3, where the model meets phi_T: -0.8, -2.4, -6.6 and -13.0 %
// (docs/validation.md section 6). At L_T = 5 (-16 %) and with sliding it does not: the whole
// table is the slow test below, which fails on those points and stays visible as such.
TEST(ThermalGupta, RollingWithinFifteenPercentUpToThermalLoadingThree) {
  for (double l_t : {0.1, 0.3, 1.0, 3.0})
    EXPECT_LE(std::abs(Deviation(l_t, 0.0)), 0.15) << "L_T " << l_t;
}

#ifdef TEHL_SLOW_TESTS
TEST(ThermalGupta, WholeTableWithinFifteenPercent) {
  for (double l_t : {0.1, 0.3, 1.0, 3.0, 5.0})
    for (double srr : {0.0, 0.25, 0.5, 1.0})
      EXPECT_LE(std::abs(Deviation(l_t, srr)), 0.15) << "L_T " << l_t << ", SRR " << srr;
}
#endif

}  // namespace
}  // namespace tehl

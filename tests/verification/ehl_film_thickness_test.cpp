// Isothermal EHL film thickness against the published fits (VALIDATION.md section 3), and the
// fits themselves against the table printed there. The fits disagree with each other by up to
// 20 %; VALIDATION.md expects a grid-converged Newton solution inside
// [0.97 x Pan-Hamrock, 1.03 x Moes] for p_H <= 2 GPa; H_min is held to Pan-Hamrock's H_min
// fit (H_min/H_c is "typically 0.7-0.85" at moderate-to-high M; see the test).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tehl/ehl/film_thickness_formulas.hpp"
#include "tehl/units.hpp"
#include "verification/ehl_moes_point.hpp"

namespace tehl {
namespace {

using testing::MoesPoint;
using testing::MoesSolver;

// VALIDATION.md section 3, table "H_M from the formula (computed)": rows M, columns L, with
// the Hertz pressure p_H [GPa] in parentheses.
constexpr double kTableL[4] = {2, 5, 10, 20};
constexpr double kTableM[7] = {10, 20, 50, 100, 200, 500, 1000};
constexpr double kTableHm[7][4] = {{2.4976, 3.6556, 5.3401, 8.2079},
                                   {2.2493, 3.3688, 4.9937, 7.7604},
                                   {1.9623, 3.0174, 4.5464, 7.1531},
                                   {1.7700, 2.7703, 4.2183, 6.6895},
                                   {1.5963, 2.5390, 3.9019, 6.2299},
                                   {1.3924, 2.2575, 3.5058, 5.6397},
                                   {1.2558, 2.0629, 3.2255, 5.2133}};
constexpr double kTablePh[7][4] = {{0.11, 0.28, 0.56, 1.13}, {0.16, 0.40, 0.80, 1.59},
                                   {0.25, 0.63, 1.26, 2.52}, {0.36, 0.89, 1.78, 3.56},
                                   {0.50, 1.26, 2.52, 5.04}, {0.80, 1.99, 3.99, 7.97},
                                   {1.13, 2.82, 5.64, 11.27}};

TEST(FilmThicknessFormulas, MoesMatchesTheValidationTable) {
  // The table is printed to 4 decimals (rounding error <= 5e-5): asserted to 1e-4.
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 4; ++j)
      EXPECT_NEAR(MoesCentralFilm(kTableM[i], kTableL[j]), kTableHm[i][j], 1e-4)
          << "M = " << kTableM[i] << ", L = " << kTableL[j];
}

TEST(FilmThicknessFormulas, DimensionalMoesAndTableHertzPressuresAgree) {
  // The point set-up (M, L) -> (U, G, W) of MoesPoint reproduces the table's p_H (printed to
  // 0.01 GPa) and MoesCentralFilmM in Moes scaling equals MoesCentralFilm(M, L) (1e-4 as above).
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 4; ++j) {
      const MoesPoint mp{kTableM[i], kTableL[j]};
      EXPECT_NEAR(mp.Hertz().max_pressure_pa / 1e9, kTablePh[i][j], 0.005 + 1e-9)
          << "M = " << mp.M << ", L = " << mp.L;
      const double hm =
          MoesCentralFilmM(mp.U(), mp.G(), mp.W(), mp.radius_m) / mp.FilmScale();
      EXPECT_NEAR(hm, kTableHm[i][j], 1e-4) << "M = " << mp.M << ", L = " << mp.L;
    }
}

TEST(FilmThicknessFormulas, PanHamrockAndMoesMatchTheSeed004PitchPoint) {
  // VALIDATION.md section 5: seed 004 pair at the pitch point, aluminium bronze on aluminium
  // bronze (E = 117 GPa, nu = 0.34 -> E' = E/(1 - nu^2), section 1), R = 8.978 mm,
  // um = 1.254 m/s, w = 116.14 kN/m. SAE 40: eta0 = 0.1140574 Pa s, Z = 0.62; SAE 90:
  // eta0 = 0.1946304 Pa s, Z = 0.5685 (Table 2), alpha from Houpert (section 1).
  // Printed: SAE 40 Moes 0.88 um, Pan-Hamrock 0.73 um; SAE 90 Moes 1.25 um, Pan-Hamrock
  // 1.05 um (two or three digits: asserted to half a unit of the last digit).
  const double e_prime = 117e9 / (1.0 - 0.34 * 0.34);
  const double r = 8.978e-3, um = 1.254, w = 116.14e3;
  struct Oil {
    double eta0, z, moes_um, ph_um;
  };
  for (const Oil& oil : {Oil{0.1140574, 0.62, 0.88, 0.73}, Oil{0.1946304, 0.5685, 1.25, 1.05}}) {
    const double alpha = oil.z * (std::log(oil.eta0) + 9.67) / 1.96e8;
    const DimensionlessGroups g = LineContactGroups(oil.eta0, alpha, um, w, r, e_prime);
    EXPECT_NEAR(MoesCentralFilmM(g.U, g.G, g.W, r) * 1e6, oil.moes_um, 0.005) << oil.eta0;
    EXPECT_NEAR(PanHamrockCentralFilmM(g.U, g.G, g.W, r) * 1e6, oil.ph_um, 0.005) << oil.eta0;
  }
}

TEST(FilmThicknessFormulas, PanHamrockIsThePublishedPowerLaw) {
  // Pan & Hamrock 1989 (VALIDATION.md section 3): H_c = 2.922 W^-0.166 U^0.692 G^0.470,
  // H_min = 1.714 W^-0.128 U^0.694 G^0.568, H = h/R. Exponents checked by scaling each group:
  // doubling U multiplies h_c by 2^0.692, doubling W by 2^-0.166, and so on.
  const double u = 1e-11, g = 5000, w = 1e-4, r = 0.01;
  const double hc = PanHamrockCentralFilmM(u, g, w, r);
  const double hm = PanHamrockMinimumFilmM(u, g, w, r);
  EXPECT_NEAR(hc / r, 2.922 * std::pow(w, -0.166) * std::pow(u, 0.692) * std::pow(g, 0.470),
              1e-12 * hc / r);
  EXPECT_NEAR(PanHamrockCentralFilmM(2 * u, g, w, r) / hc, std::pow(2.0, 0.692), 1e-12);
  EXPECT_NEAR(PanHamrockCentralFilmM(u, 2 * g, w, r) / hc, std::pow(2.0, 0.470), 1e-12);
  EXPECT_NEAR(PanHamrockCentralFilmM(u, g, 2 * w, r) / hc, std::pow(2.0, -0.166), 1e-12);
  EXPECT_NEAR(PanHamrockMinimumFilmM(2 * u, g, w, r) / hm, std::pow(2.0, 0.694), 1e-12);
  EXPECT_NEAR(PanHamrockMinimumFilmM(u, 2 * g, w, r) / hm, std::pow(2.0, 0.568), 1e-12);
  EXPECT_NEAR(PanHamrockMinimumFilmM(u, g, 2 * w, r) / hm, std::pow(2.0, -0.128), 1e-12);
}

TEST(FilmThicknessFormulas, TheEstimateIsMartinsForARigidIsoviscousFilmAndMoesOtherwise) {
  // The seed 004 pitch point of the test above (SAE 40): Moes 0.88 um (VALIDATION.md section
  // 5); rigid and isoviscous, Martin's h0 = 4.896 eta0 um R / w (VALIDATION.md section 2).
  const double e_prime = 117e9 / (1.0 - 0.34 * 0.34);
  const double r = 8.978e-3, um = 1.254, w = 116.14e3, eta0 = 0.1140574;
  const double alpha = 0.62 * (std::log(eta0) + 9.67) / 1.96e8;
  EXPECT_NEAR(EstimatedCentralFilmM(eta0, alpha, um, w, r, e_prime, true) * 1e6, 0.88, 0.005);
  EXPECT_NEAR(EstimatedCentralFilmM(eta0, 0.0, um, w, r, e_prime, false), 4.896 * eta0 * um * r / w,
              1e-15);
  // A rigid piezoviscous film has no closed form here: Moes' groups with the solids' E'.
  const DimensionlessGroups g = LineContactGroups(eta0, alpha, um, w, r, e_prime);
  EXPECT_DOUBLE_EQ(EstimatedCentralFilmM(eta0, alpha, um, w, r, e_prime, false),
                   MoesCentralFilmM(g.U, g.G, g.W, r));
}

// Table points with p_H <= 2 GPa solved at the default grid n = 513.
class FilmThicknessVerification : public ::testing::TestWithParam<std::pair<double, double>> {};

TEST_P(FilmThicknessVerification, CentralFilmLiesBetweenPanHamrockAndMoes) {
  const MoesPoint mp{GetParam().first, GetParam().second};
  ASSERT_LE(mp.Hertz().max_pressure_pa, 2e9);
  MoesSolver ms(mp, 513);
  FilmState st;
  const LineContactSolver::Summary sum = ms.solver.SolveSteady(mp.Conditions(), &st);
  ASSERT_TRUE(sum.usable()) << sum.BriefReport();
  const double hc = ms.Hc(st), hmin = ms.Hmin(st);
  std::printf(
      "M = %g L = %g p_H = %.3f GPa: H_c = %.4f H_min = %.4f (PH %.4f, Moes %.4f), "
      "H_c/PH = %.4f H_c/Moes = %.4f H_min/H_c = %.4f H_min/PH_min = %.4f, %d iterations\n",
      mp.M, mp.L, mp.Hertz().max_pressure_pa / 1e9, hc, hmin, mp.PanHamrockHc(), mp.MoesHc(),
      hc / mp.PanHamrockHc(), hc / mp.MoesHc(), hmin / hc, hmin / mp.PanHamrockHmin(),
      sum.iterations);
  EXPECT_GE(hc, 0.97 * mp.PanHamrockHc());
  EXPECT_LE(hc, 1.03 * mp.MoesHc());
  // H_min against Pan & Hamrock's own fit for it (VALIDATION.md section 3): measured 1.000 -
  // 1.044 at these points. (VALIDATION.md's "H_min / H_c typically 0.7-0.85" is for moderate
  // to high M; at these M = 10-50 the two Pan-Hamrock fits themselves give 0.82-0.93, and the
  // film 0.82-0.89, so the ratio is held to its lower bound only.)
  EXPECT_NEAR(hmin / mp.PanHamrockHmin(), 1.0, 0.06);
  EXPECT_GT(hmin / hc, 0.7);
  EXPECT_LT(sum.load_error, 1e-6);  // VALIDATION.md section 2: load balance 1e-6
}

INSTANTIATE_TEST_SUITE_P(TablePoints, FilmThicknessVerification,
                         ::testing::Values(std::pair{10.0, 5.0}, std::pair{20.0, 5.0},
                                           std::pair{50.0, 5.0}, std::pair{10.0, 10.0},
                                           std::pair{20.0, 10.0}, std::pair{50.0, 10.0}));

}  // namespace
}  // namespace tehl

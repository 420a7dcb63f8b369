// The Ree-Eyring film (effect non_newtonian, docs/theory.md "Ree-Eyring film") against its
// analytic limits:
//   - the wall stress of a uniform film without pressure gradient is the Ree-Eyring Couette
//     stress tau0 asinh(eta du / (h tau0)) (K.L. Johnson and J.L. Tevaarwerk, Proc. R. Soc.
//     Lond. A 356 (1977) 215-236, eq. 2.2 with a single Eyring element);
//   - for tau0 -> infinity it is the Newtonian wall stress eta du / h - h p' / 2;
//   - the law's slope d gdot / d tau equals a finite difference, with and without a limiting
//     stress;
//   - the friction a solved disc reports is the x-integral of those Couette stresses (an
//     isothermal film: eta(p) uniform across it), and with the energy equation it lies between
//     the integrals at the coldest and the hottest point of each column;
//   - hard sliding thermal discs settle (the coupling mixes temperature and Eyring factor in
//     one Anderson step), with their energy balance closed.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ehl/eyring_wall_stress.hpp"
#include "tehl/lubricant/lubricant.hpp"
#include "verification/thermal_disc_case.hpp"

namespace tehl {
namespace {

using internal::EyringLaw;
using internal::EyringWallStress;
using testing::Sae40;
using testing::ThermalDisc;

TEST(EyringWallStress, UniformFilmWithoutGradientIsTheAsinhLaw) {
  EyringLaw law;
  law.tau0 = 5e6;
  const int nz = 11;
  for (double eta : {1e-2, 1.0, 1e2, 1e4, 1e6}) {
    for (double du : {-3.0, 0.01, 0.5, 10.0}) {
      const double h = 1e-6;
      const std::vector<double> etas(nz, eta);
      const double t = EyringWallStress(law, etas.data(), nz, h, 0.0, du, 0.0);
      const double exact = law.tau0 * std::asinh(eta * du / (h * law.tau0));
      EXPECT_NEAR(t, exact, 1e-9 * std::abs(exact)) << "eta " << eta << " du " << du;
    }
  }
}

// A film whose viscosity varies across it (a thermal film), without pressure gradient: the
// stress is uniform, gdot(xi) = tau0 sinh(tau / tau0) / eta(xi) [/ (1 - (tau / tau_L)^2)], so
// h int gdot dxi = du gives the asinh law with the harmonic mean viscosity (trapezoidal in
// xi, as the solver integrates) and, with a limiting stress, a root of that integral, checked
// here by summing the rates node by node.
TEST(EyringWallStress, VaryingViscosityWithoutGradientSolvesTheFilmIntegral) {
  const int nz = 11;
  const double h = 8e-7;
  std::vector<double> etas(nz);
  for (int j = 0; j < nz; ++j) etas[j] = 30.0 * std::exp(-0.4 * j);  // hotter towards xi = 1
  double inv_mean = 0;
  for (int j = 0; j < nz; ++j) inv_mean += ((j == 0 || j == nz - 1) ? 0.5 : 1.0) / etas[j];
  const double eta_h = (nz - 1.0) / inv_mean;
  for (double tau_l : {0.0, 3e7, 8e6}) {
    EyringLaw law;
    law.tau0 = 5e6;
    law.tau_l = tau_l;
    for (double du : {-2.0, 1e-3, 0.3, 5.0}) {
      const double t = EyringWallStress(law, etas.data(), nz, h, 0.0, du, 0.0);
      if (tau_l == 0) {
        const double exact = law.tau0 * std::asinh(eta_h * du / (h * law.tau0));
        EXPECT_NEAR(t, exact, 1e-12 * std::abs(exact)) << "du " << du;
      }
      if (tau_l > 0) {
        EXPECT_LT(std::abs(t), tau_l) << "du " << du;
      }
      double flow = 0;
      for (int j = 0; j < nz; ++j)
        flow += ((j == 0 || j == nz - 1) ? 0.5 : 1.0) * law.Rate(t, etas[j]);
      flow *= h / (nz - 1.0);
      EXPECT_NEAR(flow, du, 1e-9 * std::abs(du)) << "tau_l " << tau_l << " du " << du;
    }
  }
}

TEST(EyringWallStress, LargeEyringStressIsNewtonianWithPressureGradient) {
  EyringLaw law;
  law.tau0 = 1e11;  // sinh(s) = s (1 + s^2 / 6 + ...): s <= 7e-5, a relative 1e-9 here
  const int nz = 21;
  const double h = 2e-6, du = 0.8, dpdx = -3e12;
  for (double eta : {0.1, 10.0}) {
    const std::vector<double> etas(nz, eta);
    const double t = EyringWallStress(law, etas.data(), nz, h, dpdx, du, 0.0);
    // Newtonian, tau(xi) = tau_1 + h p' xi: h/eta (tau_1 + h p'/2) = du.
    const double exact = eta * du / h - 0.5 * h * dpdx;
    EXPECT_NEAR(t, exact, 5e-9 * std::abs(exact)) << "eta " << eta;
  }
}

TEST(EyringLaw, SlopeMatchesFiniteDifference) {
  for (double tau_l : {0.0, 4e7}) {
    EyringLaw law;
    law.tau0 = 5e6;
    law.tau_l = tau_l;
    for (double tau : {-3e7, -1e6, 2e6, 1.5e7, 3.5e7}) {
      const double eta = 50.0, d = 1e-4 * law.tau0;
      const double fd = (law.Rate(tau + d, eta) - law.Rate(tau - d, eta)) / (2 * d);
      EXPECT_NEAR(law.Slope(tau, eta), fd, 1e-6 * std::abs(fd)) << "tau " << tau << " tau_l "
                                                                 << tau_l;
    }
  }
}

// The disc of thermal_disc_case.hpp with sliding, steady, Ree-Eyring (SAE 40: tau0 = 5 MPa).
struct EyringDisc {
  ThermalDisc disc;
  ContactConditions c;
  FilmState state;
  LineContactSolver::Summary summary;
  double mu = 0, mu_newtonian = 0;
  int n = 257;
};

EyringDisc SolveDisc(double um, double srr, bool thermal) {
  EyringDisc r;
  r.disc.um_m_s = um;
  r.disc.srr = srr;
  r.c = r.disc.Conditions(Sae40());
  LineContactSolver::Options o;
  o.film_nodes = 11;
  LineContactSolver solver = testing::DiscSolver(r.disc, Sae40(), r.n, thermal, o, {}, true);
  r.summary = solver.SolveSteady(r.c, &r.state);
  r.mu = solver.Friction(r.c, r.state).coefficient;
  return r;
}

// mu of Couette Eyring stresses, column i at the viscosity eta_of(i) [-].
template <class Eta>
double CouetteFriction(const EyringDisc& r, double dx, Eta eta_of) {
  const double tau0 = Sae40().eyring()->eyring_stress_pa;
  const double du = std::abs(r.c.u1_m_s - r.c.u2_m_s);
  double f = 0;
  for (int i = 0; i < r.n; ++i) {
    const double w = (i == 0 || i == r.n - 1) ? 0.5 * dx : dx;
    f += w * tau0 * std::asinh(eta_of(i) * du / (r.state.h_m[i] * tau0));
  }
  return f / r.c.load_n_per_m;
}

double Eta(double p, double t) {
  return Sae40().viscosity().Evaluate(std::max(p, 0.0), t).eta_pa_s;
}

TEST(EyringFilm, IsothermalFrictionIsTheCouetteEyringIntegral) {
  for (auto [um, srr] : {std::pair{1.0, 0.5}, std::pair{2.0, 1.0}, std::pair{0.5, 0.1}}) {
    const EyringDisc r = SolveDisc(um, srr, false);
    ASSERT_TRUE(r.summary.usable()) << r.summary.BriefReport();
    const double dx = UniformGrid::AroundHertz(r.disc.half_width_m(), r.n).dx_m();
    const double expected =
        CouetteFriction(r, dx, [&](int i) { return Eta(r.state.p_pa[i], r.c.temperature_k); });
    // The wall stresses' pressure-gradient parts cancel in the mean of the two surfaces.
    EXPECT_NEAR(r.mu, expected, 1e-8 * expected) << "um " << um << " SRR " << srr;
    // Shear thinning: the Newtonian film at 0.8 GPa would carry a stress 2-3 decades higher.
    EXPECT_GT(r.mu, 0.01);
    EXPECT_LT(r.mu, 0.15);
  }
}

TEST(EyringFilm, ThermalFrictionLiesBetweenColdestAndHottestColumnIntegrals) {
  const EyringDisc r = SolveDisc(1.544, 0.25, true);  // L_T = 0.1 of the Gupta table
  ASSERT_TRUE(r.summary.usable()) << r.summary.BriefReport();
  const Eigen::MatrixXd& t = r.state.temperature.t_k;
  const double dx = UniformGrid::AroundHertz(r.disc.half_width_m(), r.n).dx_m();
  // The wall stress grows with the viscosity at every depth, so a column's stress lies between
  // the uniform films at its hottest and its coldest temperature.
  const double upper =
      CouetteFriction(r, dx, [&](int i) { return Eta(r.state.p_pa[i], t.row(i).minCoeff()); });
  const double lower =
      CouetteFriction(r, dx, [&](int i) { return Eta(r.state.p_pa[i], t.row(i).maxCoeff()); });
  EXPECT_GT(r.state.temperature.MaxTemperature() - r.c.temperature_k, 5.0);  // really heated
  EXPECT_LE(r.mu, upper * (1 + 1e-9));
  EXPECT_GE(r.mu, lower * (1 - 1e-9));
}

// Points of the Gupta table (docs/validation.md section 6) whose Ree-Eyring coupling did not
// settle in 40 iterations while the Eyring factor was under-relaxed on its own: 80-290 K hotter
// than the inlet, with the pressure spike moving between coupling iterations.
TEST(EyringFilm, HotSlidingThermalDiscsSettle) {
  const Lubricant& oil = Sae40();
  for (auto [l_t, srr] : {std::pair{0.3, 1.0}, std::pair{1.0, 0.5}, std::pair{3.0, 0.5}}) {
    const EyringDisc r = SolveDisc(testing::SpeedForLoading(oil, l_t), srr, true);
    ASSERT_TRUE(r.summary.usable()) << "L_T " << l_t << " SRR " << srr << ": "
                                    << r.summary.BriefReport();
    LineContactSolver::Options defaults;
    EXPECT_LT(r.summary.temperature_change_k, defaults.thermal_tolerance_k);
    EXPECT_LT(r.summary.energy_balance_error, 1e-4);  // VALIDATION.md section 4 asks 1e-2
    EXPECT_GT(r.state.temperature.MaxTemperature() - r.c.temperature_k, 80.0);
  }
}

}  // namespace
}  // namespace tehl

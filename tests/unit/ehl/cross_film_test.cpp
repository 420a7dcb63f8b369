// The generalized Reynolds coefficients (Yang & Wen 1990) against the classical limit, an
// analytic fluidity profile, finite differences, and the mass balance of the velocity profile.
#include "ehl/cross_film.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ehl/reynolds_system.hpp"
#include "support/test_lubricants.hpp"

namespace tehl::internal {
namespace {

// Uniform eta and rho: Phi = rho/eta and F = rho (u1 + u2)/2, the classical Reynolds
// equation (derivation in ehl/cross_film.hpp; the trapezoidal rule is exact for the linear A, B).
TEST(CrossFilm, UniformFilmGivesTheClassicalCoefficients) {
  const int nz = 7;
  std::vector<double> eta(nz, 0.08), rho(nz, 870.0);
  const double u1 = 1.7, u2 = 0.4;
  const CrossFilmCoefficients c = CrossFilmIntegrals(eta.data(), nullptr, rho.data(), nullptr,
                                                     nz, u1, u2);
  EXPECT_NEAR(c.phi, 870.0 / 0.08, 1e-12 * 870.0 / 0.08);
  EXPECT_NEAR(c.flux, 870.0 * 0.5 * (u1 + u2), 1e-12 * 870.0);
  EXPECT_NEAR(c.rho_e, 870.0, 1e-12 * 870.0);
}

// Linear fluidity 1/eta = a + b xi, constant rho: A = a xi + b xi^2/2, B = a xi^2/2 + b xi^3/3,
// I0 = a + b/2, I1 = a/2 + b/3, int A = a/2 + b/6, int B = a/6 + b/12, so
// Phi = 12 rho [(a/2 + b/6)(a/2 + b/3)/(a + b/2) - (a/6 + b/12)] and
// F = rho (a/2 + b/6)(u2 - u1)/(a + b/2) + rho u1. A linear fluidity is its own piecewise-linear
// interpolant, so the integrals are exact (cross_film.hpp) at any nz.
TEST(CrossFilm, LinearFluidityIsIntegratedExactly) {
  const double a = 10.0, b = 40.0, rho = 850.0, u1 = 2.0, u2 = 0.5;
  const double phi_exact =
      12 * rho * ((a / 2 + b / 6) * (a / 2 + b / 3) / (a + b / 2) - (a / 6 + b / 12));
  const double f_exact = rho * (a / 2 + b / 6) * (u2 - u1) / (a + b / 2) + rho * u1;
  for (int nz : {2, 5, 11}) {
    std::vector<double> eta(nz), r(nz, rho);
    for (int j = 0; j < nz; ++j) eta[j] = 1.0 / (a + b * j / (nz - 1.0));
    const CrossFilmCoefficients c =
        CrossFilmIntegrals(eta.data(), nullptr, r.data(), nullptr, nz, u1, u2);
    EXPECT_NEAR(c.phi, phi_exact, 1e-12 * phi_exact) << nz;
    EXPECT_NEAR(c.flux, f_exact, 1e-12 * std::abs(f_exact)) << nz;
  }
}

// An exponential viscosity across the film (a hot mid-plane), eta = eta0 exp(-k xi), constant
// rho: I0 = (e^k - 1)/(k eta0) and the coefficients converge under refinement at the order of
// the piecewise-linear fluidity, 2; the reference is the same integral at nz = 2049.
TEST(CrossFilm, SmoothViscosityProfileConvergesAtSecondOrder) {
  const double eta0 = 0.1, k = 3.0, rho = 860.0, u1 = 1.5, u2 = 0.5;
  auto coeffs = [&](int nz) {
    std::vector<double> eta(nz), r(nz, rho);
    for (int j = 0; j < nz; ++j) eta[j] = eta0 * std::exp(-k * j / (nz - 1.0));
    return CrossFilmIntegrals(eta.data(), nullptr, r.data(), nullptr, nz, u1, u2);
  };
  const CrossFilmCoefficients ref = coeffs(2049);
  EXPECT_NEAR(ref.i0, (std::exp(k) - 1) / (k * eta0), 1e-6 * ref.i0);
  double prev = 0;
  for (int nz : {9, 17, 33, 65}) {
    const double err = std::abs(coeffs(nz).phi - ref.phi);
    if (prev > 0) {
      EXPECT_NEAR(std::log2(prev / err), 2.0, 0.15) << nz;
    }
    prev = err;
  }
}

// Pressure derivatives against central differences, with eta(p, T_j) and rho(p, T_j) of a
// Roelands / Dowson-Higginson oil over a temperature profile across the film.
TEST(CrossFilm, PressureDerivativesMatchCentralDifferences) {
  const Lubricant oil = tehl::testing::ReferenceOil();
  const int nz = 9;
  auto at = [&](double p, std::vector<double>* eta, std::vector<double>* deta,
                std::vector<double>* rho, std::vector<double>* drho) {
    for (int j = 0; j < nz; ++j) {
      const double xi = j / (nz - 1.0);
      const double t = 313.15 + 30.0 * xi * (1.3 - xi);
      const ViscosityValue v = oil.viscosity().Evaluate(p, t);
      const DensityValue d = oil.density().Evaluate(p, t);
      (*eta)[j] = v.eta_pa_s;
      (*deta)[j] = v.deta_dp;
      (*rho)[j] = d.rho_kg_m3;
      (*drho)[j] = d.drho_dp;
    }
  };
  std::vector<double> eta(nz), deta(nz), rho(nz), drho(nz);
  for (double p : {1e7, 3e8, 8e8}) {
    at(p, &eta, &deta, &rho, &drho);
    const auto c = CrossFilmIntegrals(eta.data(), deta.data(), rho.data(), drho.data(), nz,
                                      1.5, 0.7);
    const double dp = 1e-5 * p;
    at(p + dp, &eta, &deta, &rho, &drho);
    const auto cp = CrossFilmIntegrals(eta.data(), nullptr, rho.data(), nullptr, nz, 1.5, 0.7);
    at(p - dp, &eta, &deta, &rho, &drho);
    const auto cm = CrossFilmIntegrals(eta.data(), nullptr, rho.data(), nullptr, nz, 1.5, 0.7);
    EXPECT_NEAR(c.dphi_dp, (cp.phi - cm.phi) / (2 * dp), 1e-6 * std::abs(c.dphi_dp)) << p;
    EXPECT_NEAR(c.dflux_dp, (cp.flux - cm.flux) / (2 * dp), 1e-6 * std::abs(c.dflux_dp)) << p;
    EXPECT_NEAR(c.drho_e_dp, (cp.rho_e - cm.rho_e) / (2 * dp), 1e-6 * std::abs(c.drho_e_dp));
  }
}

// Scaling eta and d(eta)/dp by lambda scales Phi and dPhi/dp by 1/lambda and leaves F and
// dF/dp unchanged (Phi is linear in the fluidity 1/eta; F depends on its shape only). At
// lambda = 1e200 the fluidity integral I0 is ~1e-200, whose square underflows: the derivatives
// must come out finite and scaled, not 0/0 (analysis of the formulas in cross_film.hpp).
TEST(CrossFilm, AVeryViscousFilmKeepsFiniteScaledDerivatives) {
  const Lubricant oil = tehl::testing::ReferenceOil();
  const int nz = 11;
  const double p = 5e8;
  std::vector<double> eta(nz), deta(nz), rho(nz), drho(nz);
  for (int j = 0; j < nz; ++j) {
    const double xi = j / (nz - 1.0);
    const ViscosityValue v = oil.viscosity().Evaluate(p, 313.15 + 60.0 * xi * (1.0 - xi));
    const DensityValue d = oil.density().Evaluate(p, 313.15);
    eta[j] = v.eta_pa_s;
    deta[j] = v.deta_dp;
    rho[j] = d.rho_kg_m3;
    drho[j] = d.drho_dp;
  }
  const auto ref = CrossFilmIntegrals(eta.data(), deta.data(), rho.data(), drho.data(), nz, 1.5,
                                      0.7);
  for (double lambda : {1e100, 1e200, 1e250}) {
    std::vector<double> e2(nz), d2(nz);
    for (int j = 0; j < nz; ++j) {
      e2[j] = lambda * eta[j];
      d2[j] = lambda * deta[j];
    }
    const auto c = CrossFilmIntegrals(e2.data(), d2.data(), rho.data(), drho.data(), nz, 1.5, 0.7);
    ASSERT_TRUE(std::isfinite(c.dphi_dp) && std::isfinite(c.dflux_dp)) << lambda;
    EXPECT_NEAR(c.phi * lambda, ref.phi, 1e-12 * std::abs(ref.phi)) << lambda;
    EXPECT_NEAR(c.dphi_dp * lambda, ref.dphi_dp, 1e-12 * std::abs(ref.dphi_dp)) << lambda;
    EXPECT_NEAR(c.flux, ref.flux, 1e-12 * std::abs(ref.flux)) << lambda;
    EXPECT_NEAR(c.dflux_dp, ref.dflux_dp, 1e-9 * std::abs(ref.dflux_dp)) << lambda;
  }
}

// The velocity profile meets both walls, the trapezoidal quadrature of rho u converges to the
// flow F h - Phi h^3 p'/12 of the coefficients (the identity derived in ehl/cross_film.hpp),
// the shear stress is linear with slope h dp/dx in xi, and tau = eta du/dz by central
// differences.
TEST(CrossFilm, VelocityProfileCarriesTheReynoldsFlow) {
  const int nz = 41;
  const double h = 4e-7, dpdx = -2e12, u1 = 1.2, u2 = 0.3;
  std::vector<double> eta(nz), rho(nz), u(nz), tau(nz);
  for (int j = 0; j < nz; ++j) {
    const double xi = j / (nz - 1.0);
    eta[j] = 0.05 * std::exp(-1.5 * xi * (1 - 0.4 * xi));
    rho[j] = 860.0 - 20.0 * xi;
  }
  CrossFilmProfile(eta.data(), nz, h, dpdx, u1, u2, u.data(), tau.data());
  EXPECT_DOUBLE_EQ(u[0], u1);
  EXPECT_NEAR(u[nz - 1], u2, 1e-14);
  const auto c = CrossFilmIntegrals(eta.data(), nullptr, rho.data(), nullptr, nz, u1, u2);
  double q = 0;
  for (int j = 0; j < nz; ++j) q += ((j == 0 || j == nz - 1) ? 0.5 : 1.0) * rho[j] * u[j];
  q *= h / (nz - 1);
  const double q_coeff = c.flux * h - c.phi * h * h * h * dpdx / 12.0;
  // Trapezoidal error of a smooth integrand, O(1/nz^2): about 1e-4 here.
  EXPECT_NEAR(q, q_coeff, 1e-3 * std::abs(q_coeff));
  const double dz = h / (nz - 1);
  for (int j = 1; j < nz - 1; ++j) {
    EXPECT_NEAR(tau[j + 1] - tau[j], h * dpdx / (nz - 1), 1e-9 * std::abs(h * dpdx));
    const double fd = eta[j] * (u[j + 1] - u[j - 1]) / (2 * dz);
    EXPECT_NEAR(tau[j], fd, 2e-3 * (std::abs(tau[j]) + std::abs(h * dpdx))) << j;
  }
}

// The generalized residual of the Reynolds system with a uniform temperature T0 equals the
// classical one (the limit above, node by node), and its local derivatives match central
// differences with a non-uniform temperature field.
TEST(CrossFilm, GeneralizedReynoldsReducesToClassicalAndHasExactDerivatives) {
  const Lubricant oil = tehl::testing::ReferenceOil();
  const int n = 31, nz = 5;
  const double dx = 5e-6, u1 = 1.0, u2 = 1.6, um = 0.5 * (u1 + u2);
  Eigen::VectorXd p(n), h(n);
  for (int i = 0; i < n; ++i) {
    const double x = (i - n / 2) * dx / 6e-5;
    p[i] = (i == 0 || i == n - 1) ? 0.0 : 4e8 * std::max(0.02, 1 - x * x);
    h[i] = 2e-7 * (1.0 + 0.5 * x * x);
  }
  FluidLaws classical;
  classical.viscosity = &oil.viscosity();
  classical.density = &oil.density();
  classical.temperature_k = tehl::testing::kReferenceT0;
  Eigen::MatrixXd t0 = Eigen::MatrixXd::Constant(n, nz, classical.temperature_k);
  FluidLaws general = classical;
  general.film_temperature_k = &t0;
  general.u1_m_s = u1;
  general.u2_m_s = u2;
  TimeDerivative none;
  ReynoldsSystem a(n, dx, 2), b(n, dx, 2);
  a.Evaluate(classical, um, p, h, none, true);
  b.Evaluate(general, um, p, h, none, true);
  const double scale = a.residual().cwiseAbs().maxCoeff();
  EXPECT_LT((a.residual() - b.residual()).cwiseAbs().maxCoeff(), 1e-10 * scale);

  Eigen::MatrixXd tf(n, nz);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < nz; ++j) tf(i, j) = 313.15 + 25.0 * std::sin(0.1 * i) * j / (nz - 1.0);
  general.film_temperature_k = &tf;
  b.Evaluate(general, um, p, h, none, true);
  const auto dp = b.dr_dp();
  const auto dh = b.dr_dh();
  for (int i = 3; i < n - 3; ++i) {
    for (int col = 0; col < 4; ++col) {
      const int k = i - 2 + col;
      Eigen::VectorXd pp = p, pm = p, hp = h, hm = h;
      const double ep = 1e-6 * p[k] + 1.0, eh = 1e-6 * h[k];
      pp[k] += ep;
      pm[k] -= ep;
      hp[k] += eh;
      hm[k] -= eh;
      ReynoldsSystem s(n, dx, 2);
      s.Evaluate(general, um, pp, h, none, false);
      const double rp = s.residual()[i];
      s.Evaluate(general, um, pm, h, none, false);
      const double fd_p = (rp - s.residual()[i]) / (2 * ep);
      s.Evaluate(general, um, p, hp, none, false);
      const double rhp = s.residual()[i];
      s.Evaluate(general, um, p, hm, none, false);
      const double fd_h = (rhp - s.residual()[i]) / (2 * eh);
      const double row_p = dp.row(i).cwiseAbs().maxCoeff(), row_h = dh.row(i).cwiseAbs().maxCoeff();
      EXPECT_NEAR(dp(i, col), fd_p, 1e-5 * row_p) << i << " " << col;
      EXPECT_NEAR(dh(i, col), fd_h, 1e-5 * row_h) << i << " " << col;
    }
  }
}

}  // namespace
}  // namespace tehl::internal

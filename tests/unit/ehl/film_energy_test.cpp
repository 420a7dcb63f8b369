// Film energy equation with moving-solid surface temperatures (seed 004 eqs. 9-15, DESIGN.md
// sections 4-5): analytic film profiles, exact invariants, the energy balance of VALIDATION.md
// section 4, the transient limit and order, grid convergence and a low-speed case.
#include "tehl/ehl/film_energy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "support/test_lubricants.hpp"
#include "tehl/error.hpp"
#include "unit/ehl/film_flow_fields.hpp"

namespace tehl {
namespace {

using testing::Bronze;
using testing::EhlLikeField;
using testing::EhlLikeParameters;
using testing::EnergyTestOil;

constexpr double kT0 = testing::kReferenceT0;

FilmEnergySolver::Options Opts(int nz, FilmEnergySolver::Walls walls) {
  FilmEnergySolver::Options o;
  o.film_nodes = nz;
  o.walls = walls;
  o.tolerance_k = 1e-9;
  return o;
}

// A steady solve of `f` between walls held at T0 (the analytic film tests).
FilmEnergySolver::Summary SolveBetweenFixedWalls(const UniformGrid& g,
                                                 const Lubricant& oil,
                                                 int nz,
                                                 const FilmFlowField& f,
                                                 FilmTemperature* t) {
  FilmEnergySolver solver(g, oil, Bronze(), Bronze(), kT0,
                          Opts(nz, FilmEnergySolver::Walls::kFixedTemperature));
  return solver.Solve(f, nullptr, 0.0, t);
}

// A fully developed film between fixed walls: h, dp/dx and u(xi) the same at every x, with
// u = U xi + P xi (1 - xi) and heating eta (du/dz)^2, eta = 1 Pa s, h = 1 um, U = 10 m/s.
struct ParallelFilm {
  double eta = 1.0, h = 1e-6, u = 10.0, p = 0.0;
  FilmFlowField Field(const UniformGrid& g, int nz) const {
    FilmFlowField f;
    f.p_pa = Eigen::VectorXd::Zero(g.size());
    f.h_m = Eigen::VectorXd::Constant(g.size(), h);
    f.u_m_s.resize(g.size(), nz);
    f.heating_w_m3.resize(g.size(), nz);
    for (int j = 0; j < nz; ++j) {
      const double xi = static_cast<double>(j) / (nz - 1);
      const double dudxi = u + p * (1 - 2 * xi);
      f.u_m_s.col(j).setConstant(u * xi + p * xi * (1 - xi));
      f.heating_w_m3.col(j).setConstant(eta * dudxi * dudxi / (h * h));
    }
    f.u1_m_s = 0;
    f.u2_m_s = u;
    return f;
  }
  // -k/h^2 T'' = (eta/h^2)(a + b xi)^2, T(0) = T(1) = T0, a = U + P, b = -2P: with
  // F(xi) = (a + b xi)^4 / (12 b^2), T - T0 = -(eta/k)[F(xi) - F(0) - (F(1) - F(0)) xi]
  // (integrate twice; F'' = (a + b xi)^2). P = 0: T - T0 = eta U^2/(2k) xi (1 - xi).
  double Exact(double xi, double k) const {
    if (p == 0) return eta * u * u / (2 * k) * xi * (1 - xi);
    const double a = u + p, b = -2 * p;
    auto f = [&](double s) { return std::pow(a + b * s, 4) / (12 * b * b); };
    return -(eta / k) * (f(xi) - f(0) - (f(1) - f(0)) * xi);
  }
};

// The film at the outlet end of a 2 mm long grid, 15 thermal entry lengths
// rho cp U h^2 / k = 0.13 mm long: fully developed.
Eigen::MatrixXd SolveParallel(const ParallelFilm& pf, int nz, FilmTemperature* out = nullptr) {
  const Lubricant oil = testing::IsoviscousOil(pf.eta);  // rho 870, k 0.13, cp 2000, beta 0
  const UniformGrid g(0.0, 2e-3, 41);
  FilmEnergySolver solver(g, oil, Bronze(), Bronze(), kT0,
                          Opts(nz, FilmEnergySolver::Walls::kFixedTemperature));
  FilmTemperature t;
  const auto s = solver.Solve(pf.Field(g, nz), nullptr, 0.0, &t);
  EXPECT_TRUE(s.usable()) << s.BriefReport();
  EXPECT_EQ(s.iterations, 1);  // constant properties: a linear problem
  // The field conserves mass cell by cell (no defect): the discrete energy balance is exact.
  EXPECT_LT(s.mass_defect, 1e-14);
  EXPECT_LT(s.balance.RelativeError(), 1e-10) << s.BriefReport();
  if (out) *out = t;
  return t.t_k;
}

TEST(FilmEnergySolver, PlaneCouetteGivesTheParabolicProfileBetweenFixedWalls) {
  // T - T0 = eta U^2/(2k) xi (1 - xi), max eta U^2/(8k) at mid-film; the three-point
  // conduction stencil is exact for a quadratic, so only round-off remains. The heat flux into
  // each wall is k dT/dz = eta U^2/(2h), half of the heat generated, eta U^2/h per unit area.
  const ParallelFilm pf;
  FilmTemperature t;
  const Eigen::MatrixXd temp = SolveParallel(pf, 21, &t);
  const int last = static_cast<int>(temp.rows()) - 1;
  const double k = 0.13, peak = pf.eta * pf.u * pf.u / (8 * k);
  for (int j = 0; j < 21; ++j) {
    const double xi = j / 20.0;
    EXPECT_NEAR(temp(last, j) - kT0, pf.Exact(xi, k), 1e-9 * peak) << j;
  }
  EXPECT_NEAR(temp(last, 10) - kT0, peak, 1e-9 * peak);
  const double wall_flux = pf.eta * pf.u * pf.u / (2 * pf.h);
  EXPECT_NEAR(t.q1_w_m2[last], wall_flux, 1e-9 * wall_flux);
  EXPECT_NEAR(t.q2_w_m2[last], wall_flux, 1e-9 * wall_flux);
}

// Heating that falls as the film warms, g(T) = H exp(-beta (T - T0)) (FilmFlowField::
// heating_decay_1_k, the Couette heating of a viscosity eta ~ exp(-beta T)), in a film at rest
// between walls held at T0: -k T'' = H exp(-beta (T - T0)), T(0) = T(h) = T0. With
// v = -beta (T - T0) this is v'' = lambda e^v, lambda = H beta / k, whose solution symmetric
// about mid-film is v = 2 ln cos(b h/2) - 2 ln cos(b (z - h/2)) with 2 b^2 = lambda cos^2(b h/2)
// (substitute: v'' = 2 b^2 / cos^2(b (z - h/2)) = lambda e^v). So, with s = b h / 2 the root of
// 8 s^2 = mu cos^2 s, mu = H beta h^2 / k:
//   T - T0 = (2/beta) [ln cos(s (2 xi - 1)) - ln cos s].
// mu = 40: the rise at mid-film is 1.472/beta, against 5/beta for a heating that does not fall
// (H h^2 / (8k)), so the decay is far from a small correction.
double DecayingHeatingExact(double xi, double mu, double beta) {
  double lo = 0, hi = M_PI / 2;  // 8 s^2 - mu cos^2 s increases from -mu to 2 pi^2 on [0, pi/2]
  for (int it = 0; it < 200; ++it) {
    const double s = 0.5 * (lo + hi);
    (8 * s * s - mu * std::cos(s) * std::cos(s) > 0 ? hi : lo) = s;
  }
  const double s = 0.5 * (lo + hi);
  return 2 / beta * (std::log(std::cos(s * (2 * xi - 1))) - std::log(std::cos(s)));
}

// Conduction along x (docs/theory.md, "Energy equation"): a film at rest, as thick as it is
// long (h = L = 0.1 mm), between walls held at T0, heated by H = G (1 + cos(pi x/L)) sin(pi xi)
// (a dissipation, so >= 0). No heat crosses the two ends, so -k (T_xx + T_zz) = H with T = T0
// at both walls and T_x = 0 at both ends, solved by two modes,
//   T - T0 = G sin(pi xi) [h^2 / (k pi^2) + cos(pi x/L) / (k pi^2 (1/L^2 + 1/h^2))];
// the second has half the amplitude it would have without conduction along x. The central
// stencils in x and xi: second order in (dx, dxi) refined together.
TEST(FilmEnergySolver, ConductionAlongXInAFilmAtRestGivesTheSeparableSolution) {
  const double length = 1e-4, h = 1e-4, k = 0.13, g_w_m3 = 1e9;
  const Lubricant oil = testing::IsoviscousOil(1.0);  // k = 0.13, no thermal expansion
  const double uniform = g_w_m3 * h * h / (k * M_PI * M_PI);
  const double amplitude = g_w_m3 / (k * M_PI * M_PI * (1 / (length * length) + 1 / (h * h)));
  std::vector<double> errors;
  for (int n : {11, 21, 41}) {
    const int nz = n;
    const UniformGrid g(0.0, length, n);
    FilmFlowField f;
    f.p_pa = Eigen::VectorXd::Zero(n);
    f.h_m = Eigen::VectorXd::Constant(n, h);
    f.u_m_s = Eigen::MatrixXd::Zero(n, nz);
    f.heating_w_m3.resize(n, nz);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < nz; ++j)
        f.heating_w_m3(i, j) =
            g_w_m3 * (1 + std::cos(M_PI * g.x(i) / length)) * std::sin(M_PI * j / (nz - 1.0));
    FilmTemperature t;
    const auto sum = SolveBetweenFixedWalls(g, oil, nz, f, &t);
    ASSERT_TRUE(sum.usable()) << sum.BriefReport();
    double worst = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < nz; ++j) {
        const double exact = (uniform + amplitude * std::cos(M_PI * g.x(i) / length)) *
                             std::sin(M_PI * j / (nz - 1.0));
        worst = std::max(worst, std::abs(t.t_k(i, j) - kT0 - exact));
      }
    errors.push_back(worst / amplitude);
    // The heat generated leaves through the walls: the balance closes.
    EXPECT_LT(sum.balance.RelativeError(), 1e-6) << n;
  }
  for (size_t i = 1; i < errors.size(); ++i) {
    const double order = std::log2(errors[i - 1] / errors[i]);
    std::printf("conduction along x, refinement %zu: relative error %.3e, order %.3f\n", i,
                errors[i], order);
    EXPECT_GT(order, 1.8) << i;
  }
  // Without the conduction along x the cos mode would be twice as large: an error of
  // amplitude / amplitude = 100 % of the reference.
  EXPECT_LT(errors.back(), 2e-3);
}

TEST(FilmEnergySolver, HeatingThatFallsWithTemperatureGivesTheAnalyticProfile) {
  const double h = 1e-6, k = 0.13, beta = 0.046, mu = 40.0;
  const double heating = mu * k / (beta * h * h);     // H [W/m^3]
  const Lubricant oil = testing::IsoviscousOil(1.0);  // k = 0.13, no thermal expansion
  const UniformGrid g(0.0, 1e-4, 5);
  const double peak = DecayingHeatingExact(0.5, mu, beta);
  EXPECT_NEAR(beta * peak, 1.4719,
              1e-4);  // -2 ln cos s at the root s = 1.07121 of 8 s^2 = 40 cos^2 s
  std::vector<double> errors;
  for (int nz : {11, 21, 41}) {
    FilmFlowField f;
    f.p_pa = Eigen::VectorXd::Zero(g.size());
    f.h_m = Eigen::VectorXd::Constant(g.size(), h);
    f.u_m_s = Eigen::MatrixXd::Zero(g.size(), nz);
    f.heating_w_m3 = Eigen::MatrixXd::Constant(g.size(), nz, heating);
    f.heating_decay_1_k = Eigen::MatrixXd::Constant(g.size(), nz, beta);
    f.heating_reference_t_k = Eigen::MatrixXd::Constant(g.size(), nz, kT0);
    FilmTemperature t;
    const auto sum = SolveBetweenFixedWalls(g, oil, nz, f, &t);
    ASSERT_TRUE(sum.usable()) << sum.BriefReport();
    EXPECT_GT(sum.iterations, 1);  // nonlinear: the source is relinearized about each iterate
    double worst = 0;
    for (int i = 0; i < g.size(); ++i)
      for (int j = 0; j < nz; ++j)
        worst = std::max(
            worst, std::abs(t.t_k(i, j) - kT0 - DecayingHeatingExact(j / (nz - 1.0), mu, beta)));
    errors.push_back(worst / peak);
    // All the heat generated leaves through the walls (no flow): the balance closes.
    EXPECT_LT(sum.balance.RelativeError(), 1e-6) << nz;
  }
  for (size_t i = 1; i < errors.size(); ++i) {
    const double order = std::log2(errors[i - 1] / errors[i]);
    std::printf("decaying heating, refinement %zu: relative error %.3e, order %.3f\n", i, errors[i],
                order);
    EXPECT_GT(order, 1.8) << i;  // the central three-point stencil: second order
  }
  EXPECT_LT(errors.back(), 2e-3);
}

// Compression heating -(T/rho)(drho/dT) Dp/Dt (seed 004 eq. 9): a film at rest between walls
// held at T0, the pressure rising everywhere at D = dp/dt. With the Dowson-Higginson density
// rho = rho0 f(p) (1 - e (T - T0)) the source is c(T) T, c(T) = e D / (1 - e (T - T0)), so
//   k T'' + c(T) T = 0,  T(0) = T(h) = T0,
// which without the expansion's T-dependence is T0 cos(l (z - h/2)) / cos(l h/2), l^2 = e D/k.
// Solved here by shooting: RK4 on fine steps from z = 0 with the slope bisected until T(h) =
// T0 (an independent 1-D solution, not the solver's stencil). The film closes at dh/dt =
// -h (drho/dp / rho) dp/dt so that the compressing oil moves no mass (a film of fixed h would
// need an inflow, and the solver's continuity correction would convect heat). D = 3e12 Pa/s in a 10
// um film gives l h/2 = 0.6: a rise of about 66 K at mid-film. A sign error of the term would cool
// the film; one that ignored T in the source (c T0) would give 12 % less rise.
TEST(FilmEnergySolver, CompressionHeatingOfAFilmAtRestGivesTheShootingSolution) {
  const double h = 1e-5, e = 6.5e-4, dpdt = 3e12;
  const Lubricant oil = testing::EnergyTestOil(e, kT0);  // k(0) = 0.14 W/(m K)
  const double k = oil.conductivity().Evaluate(0.0).k_w_mk;
  const auto reference = [&](int nz) {
    const int per_cell = 400, steps = per_cell * (nz - 1);
    const double dz = h / steps;
    auto shoot = [&](double slope, std::vector<double>* nodes) {
      double t = kT0, dt = slope;
      auto f = [&](double tt) { return -e * dpdt / (1 - e * (tt - kT0)) * tt / k; };
      if (nodes) nodes->assign(1, t);
      for (int m = 0; m < steps; ++m) {  // RK4 for (T, T')
        const double k1t = dt, k1d = f(t);
        const double k2t = dt + 0.5 * dz * k1d, k2d = f(t + 0.5 * dz * k1t);
        const double k3t = dt + 0.5 * dz * k2d, k3d = f(t + 0.5 * dz * k2t);
        const double k4t = dt + dz * k3d, k4d = f(t + dz * k3t);
        t += dz / 6 * (k1t + 2 * k2t + 2 * k3t + k4t);
        dt += dz / 6 * (k1d + 2 * k2d + 2 * k3d + k4d);
        if (nodes && (m + 1) % per_cell == 0) nodes->push_back(t);
      }
      return t;
    };
    // The slope at z = 0 [K/m]: 0 ends below T0 (T'' < 0), 1e8 far above it (the linear
    // solution's is T0 l tan(l h/2) = 2.5e7); an overshoot that runs away counts as above.
    double lo = 0, hi = 1e8;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      (!(shoot(mid, nullptr) <= kT0) ? hi : lo) = mid;
    }
    std::vector<double> nodes;
    shoot(0.5 * (lo + hi), &nodes);
    return nodes;
  };
  const UniformGrid g(0.0, 1e-4, 5);
  std::vector<double> errors;
  double rise = 0;
  for (int nz : {11, 21, 41}) {
    const std::vector<double> want = reference(nz);
    rise = want[(nz - 1) / 2] - kT0;
    FilmFlowField f;
    f.p_pa = Eigen::VectorXd::Zero(g.size());
    f.h_m = Eigen::VectorXd::Constant(g.size(), h);
    f.dpdt_pa_s = Eigen::VectorXd::Constant(g.size(), dpdt);
    // The film closes as the oil compresses, so that no mass moves: d(rho h)/dt = 0 in every
    // cell (drho/dp / rho does not depend on T for this density law).
    const DensityValue d = oil.density().Evaluate(0.0, kT0);
    f.dhdt_m_s = Eigen::VectorXd::Constant(g.size(), -h * d.drho_dp / d.rho_kg_m3 * dpdt);
    f.u_m_s = Eigen::MatrixXd::Zero(g.size(), nz);
    f.heating_w_m3 = Eigen::MatrixXd::Zero(g.size(), nz);
    FilmTemperature t;
    const auto sum = SolveBetweenFixedWalls(g, oil, nz, f, &t);
    ASSERT_TRUE(sum.usable()) << sum.BriefReport();
    double worst = 0;
    for (int i = 0; i < g.size(); ++i)
      for (int j = 0; j < nz; ++j) worst = std::max(worst, std::abs(t.t_k(i, j) - want[j]));
    EXPECT_LT(sum.mass_defect, 1e-12) << nz;  // the field conserves mass
    errors.push_back(worst / rise);
    // The heat the compression makes leaves through the walls.
    EXPECT_GT(sum.balance.compression_w_m, 0.0);
    EXPECT_LT(sum.balance.RelativeError(), 1e-6) << nz;
  }
  // The closed form without the expansion's T-dependence, as a check of the scale.
  const double l = std::sqrt(e * dpdt / k);
  EXPECT_NEAR(rise, kT0 * (1 / std::cos(l * h / 2) - 1), 0.1 * rise);
  EXPECT_GT(rise, 50.0);
  for (size_t i = 1; i < errors.size(); ++i) {
    const double order = std::log2(errors[i - 1] / errors[i]);
    std::printf(
        "compression heating (rise %.2f K), refinement %zu: relative error %.3e, "
        "order %.3f\n",
        rise, i, errors[i], order);
    EXPECT_GT(order, 1.8) << i;
  }
  EXPECT_LT(errors.back(), 2e-3);
}

TEST(FilmEnergySolver, CouettePoiseuilleProfileConvergesAtSecondOrderInFilmNodes) {
  // Quartic exact profile (ParallelFilm::Exact with P = 2U, no reverse flow). The three-point
  // stencil applied to a quartic gives T'' + (dxi^2/12) T'''' exactly, and T'''' = -2 b^2 eta/k
  // is constant, so the discrete error e solves -e'' = -(dxi^2/12)(2 b^2 eta/k) exactly
  // (a quadratic, reproduced exactly by the stencil) with e = 0 on the walls:
  //   T_h - T = -(dxi^2 b^2 eta / (12 k)) xi (1 - xi)      (second order in 1/(nz-1)).
  ParallelFilm pf;
  pf.p = 2 * pf.u;
  const double k = 0.13;
  double scale = 0;
  for (int j = 0; j <= 100; ++j) scale = std::max(scale, std::abs(pf.Exact(j / 100.0, k)));
  std::vector<double> errors;
  for (int nz : {11, 21, 41, 81}) {
    const Eigen::MatrixXd temp = SolveParallel(pf, nz);
    double worst = 0;
    for (int j = 0; j < nz; ++j)
      worst = std::max(worst, std::abs(temp(temp.rows() - 1, j) - kT0 -
                                       pf.Exact(static_cast<double>(j) / (nz - 1), k)));
    errors.push_back(worst / scale);
    const double dxi = 1.0 / (nz - 1), b = -2 * pf.p;
    const Eigen::MatrixXd& tl = temp;
    for (int j = 0; j < nz; ++j) {
      const double xi = j * dxi;
      const double predicted = -(dxi * dxi * b * b * pf.eta / (12 * k)) * xi * (1 - xi);
      EXPECT_NEAR(tl(tl.rows() - 1, j) - kT0 - pf.Exact(xi, k), predicted, 1e-9 * scale) << j;
    }
  }
  for (size_t i = 1; i < errors.size(); ++i) {
    const double order = std::log2(errors[i - 1] / errors[i]);
    std::printf("nz refinement %zu: relative error %.3e, order %.3f\n", i, errors[i], order);
    EXPECT_NEAR(order, 2.0, 0.1) << i;
  }
}

TEST(FilmEnergySolver, WithoutHeatingTheInletTemperatureStaysExactly) {
  // No dissipation, beta = 0 (no compression work), reverse flow in the inlet, compressible
  // rho(p), moving solids: every term of the scheme is a difference T_ij - T_neighbour or a
  // flux q, so T = T0, q = 0 solves it exactly; steady and transient.
  const Lubricant oil = EnergyTestOil(0.0);
  const UniformGrid g = UniformGrid::AroundHertz(1e-4, 129);
  FilmFlowField f = EhlLikeField(g, 11, oil, EhlLikeParameters{});
  ASSERT_LT(f.u_m_s.minCoeff(), 0);  // reverse flow present
  f.heating_w_m3.setZero();
  f.dpdt_pa_s = Eigen::VectorXd::Constant(g.size(), 1e9);
  f.dhdt_m_s = Eigen::VectorXd::Constant(g.size(), -1e-4);
  FilmEnergySolver solver(g, oil, Bronze(), Bronze(), kT0,
                          Opts(11, FilmEnergySolver::Walls::kMovingSolids));
  FilmTemperature t;
  auto s = solver.Solve(f, nullptr, 0.0, &t);
  ASSERT_TRUE(s.usable()) << s.BriefReport();
  EXPECT_LT((t.t_k.array() - kT0).abs().maxCoeff(), 1e-12 * kT0);
  EXPECT_LT(t.q1_w_m2.cwiseAbs().maxCoeff(), 1e-6);  // W/m^2, against ~1e7 when heated
  const FilmTemperature prev = solver.Initial();
  s = solver.Solve(f, &prev, 1e-6, &t);
  ASSERT_TRUE(s.usable()) << s.BriefReport();
  EXPECT_LT((t.t_k.array() - kT0).abs().maxCoeff(), 1e-12 * kT0);
}

struct EhlRun {
  FilmEnergySolver::Summary summary;
  FilmTemperature t;
  FilmFlowField f;
};

EhlRun SolveEhl(
    int n, int nz, const EhlLikeParameters& c, double beta = 6.5e-4, double tolerance_k = 1e-6) {
  const Lubricant oil = EnergyTestOil(beta);
  const UniformGrid g = UniformGrid::AroundHertz(c.half_width_m, n);
  EhlRun r;
  r.f = EhlLikeField(g, nz, oil, c);
  FilmEnergySolver::Options o = Opts(nz, FilmEnergySolver::Walls::kMovingSolids);
  o.tolerance_k = tolerance_k;
  FilmEnergySolver solver(g, oil, Bronze(), Bronze(), kT0, o);
  r.summary = solver.Solve(r.f, nullptr, 0.0, &r.t);
  return r;
}

TEST(FilmEnergySolver, EnergyBalanceClosesWithinOnePercentWithAndWithoutReverseFlow) {
  // VALIDATION.md section 4: heat generated (shear + compression) = convected out + conducted
  // into both solids, within 1 %. Rolling with sliding (u1 = 1, u2 = 1.5 m/s, SRR 0.4).
  for (double radius : {0.1, 0.01}) {  // inlet film 2.7 h_c (no reverse flow), 13 h_c
    EhlLikeParameters c;
    c.radius_m = radius;
    // Solved to 1e-9 K: every step is a chord step (the conduction along x to the upstream
    // column is outside the factorization), so the balance holds to the solve's tolerance
    // plus round-off, and the round-off is what this test checks.
    const EhlRun r = SolveEhl(257, 11, c, 6.5e-4, 1e-9);
    ASSERT_TRUE(r.summary.usable()) << r.summary.BriefReport();
    EXPECT_EQ(r.f.u_m_s.minCoeff() < 0, radius == 0.01);
    const EnergyBalance& b = r.summary.balance;
    std::printf(
        "R = %.2f m: shear %.4g, compression %.4g, out %.4g, solid1 %.4g, solid2 %.4g"
        " W/m; error %.2e, mass defect %.2e, %d iterations, %.2f ms, T_max - T0 = %.3f K\n",
        radius, b.shear_w_m, b.compression_w_m, b.convected_out_w_m, b.into_solid1_w_m,
        b.into_solid2_w_m, b.RelativeError(), r.summary.mass_defect, r.summary.iterations,
        r.summary.wall_time_s * 1e3, r.t.MaxTemperature() - kT0);
    EXPECT_LT(b.RelativeError(), 0.01);
    // The EHL-like field's velocity profile does not conserve mass cell by cell (its pressure
    // is not a Reynolds solution on this grid: mass defect 1e-2 and 1e-1 of the mass flow).
    // The solver corrects the face fluxes to discrete continuity, so the finite-volume
    // balance then closes to round-off (docs/thermal.md, "Energy balance"); an uncorrected
    // defect left 1.2-4.9 % in the steady discs of docs/validation.md section 6.
    EXPECT_GT(r.summary.mass_defect, 1e-3);
    EXPECT_LT(b.RelativeError(), 1e-10);
    EXPECT_GT(b.convected_out_w_m, 0);
    EXPECT_GT(b.into_solid1_w_m, 0);
    EXPECT_GT(b.into_solid2_w_m, 0);
    // The surfaces are the moving-heat-source integrals of the fluxes the film delivers.
    const MovingHeatSource src(UniformGrid::AroundHertz(c.half_width_m, 257));
    const Eigen::VectorXd rise1 = src.Rise(Bronze(), c.u1_m_s, r.t.q1_w_m2);
    const Eigen::VectorXd rise2 = src.Rise(Bronze(), c.u2_m_s, r.t.q2_w_m2);
    const double scale = r.t.MaxTemperature() - kT0;
    EXPECT_LT((r.t.t1_k.array() - kT0 - rise1.array()).abs().maxCoeff(), 1e-6 * scale);
    EXPECT_LT((r.t.t2_k.array() - kT0 - rise2.array()).abs().maxCoeff(), 1e-6 * scale);
  }
}

TEST(FilmEnergySolver, TemperatureRiseConvergesInFilmNodesAndGridNodes) {
  // Case 4 with reverse flow: T_max - T0 changes by at most 2 % between nz = 11 and 21 and
  // between n = 257 and 513.
  EhlLikeParameters c;
  const double coarse = SolveEhl(257, 11, c).t.MaxTemperature() - kT0;
  const double fine_z = SolveEhl(257, 21, c).t.MaxTemperature() - kT0;
  const double fine_x = SolveEhl(513, 11, c).t.MaxTemperature() - kT0;
  std::printf("T_max - T0: %.4f K (n 257, nz 11), %.4f K (nz 21), %.4f K (n 513)\n", coarse, fine_z,
              fine_x);
  EXPECT_LT(std::abs(fine_z - coarse), 0.02 * fine_z);
  EXPECT_LT(std::abs(fine_x - coarse), 0.02 * fine_x);
}

TEST(FilmEnergySolver, PureRollingAtLowSpeedWarmsTheFilmByLessThanOneKelvin) {
  // u1 = u2 = 0.05 m/s, thin film 0.1 um: no Couette shear; the heat is the Poiseuille
  // dissipation and the compression work only. Estimate: compression ~ beta T0 um p_H h_c
  // ~ 6.5e-4 * 313 * 0.05 * 5e8 * 1e-7 = 0.5 W/m over the inlet flank; the surface rise of a
  // 1 W/m source over 2b = 0.2 mm is F q 2 sqrt(2b) ~ 1/(sqrt(pi 7890 375 55 0.05)) *
  // (1 / 2e-4) * 2 sqrt(2e-4) ~ 0.03 K: far below 1 K. The solve must also converge here,
  // where the solids are slow (F large).
  EhlLikeParameters c;
  c.u1_m_s = c.u2_m_s = 0.05;
  c.central_film_m = 1e-7;
  const EhlRun r = SolveEhl(257, 11, c);
  ASSERT_TRUE(r.summary.usable()) << r.summary.BriefReport();
  const double rise = r.t.MaxTemperature() - kT0;
  std::printf("low speed: T_max - T0 = %.4f K, balance error %.2e, %d iterations\n", rise,
              r.summary.balance.RelativeError(), r.summary.iterations);
  EXPECT_LT(rise, 1.0);
  EXPECT_GT(rise, 0.0);
  EXPECT_LT(r.summary.balance.RelativeError(), 0.01);
}

TEST(FilmEnergySolver, StronglyCoupledPolymerSolidsSatisfyTheWholeHistory) {
  // The solve keeps only the near band of the moving-heat-source history in its factorized
  // matrix (Options::history_near_cells) and lags the far part. Steel or bronze surfaces warm
  // little per unit flux (film conduction k/h times F 2 sqrt(L) ~ 0.1); here polymer-like
  // solids (rho 1300 kg/m^3, c 1340 J/(kg K), k 0.25 W/(m K): effusivity 660 against 12 600
  // for bronze) under a 0.1 um film make that ~ 200 times larger. With the default band, with
  // none (the lagged history converges too slowly: the solve goes on with GMRES steps on the
  // whole history) and with the whole history, contract: each converges, its surfaces are the
  // O(n^2) moving-heat-source sums of its fluxes (the derivation in surface_temperature_test.cpp)
  // to 1e-6 of the rise, the balance closes within 1 % (VALIDATION.md section 4), and the three
  // agree to ten times the tolerance.
  const SolidThermal polymer = testing::Polymer();
  const testing::ThinEhlFilm film;
  const EhlLikeParameters& c = film.c;
  const Lubricant& oil = film.oil;
  const UniformGrid& g = film.g;
  const FilmFlowField& f = film.f;
  const MovingHeatSource src(g);
  Eigen::MatrixXd whole;
  for (int near : {1000, FilmEnergySolver::Options{}.history_near_cells, 0}) {
    FilmEnergySolver::Options o = Opts(11, FilmEnergySolver::Walls::kMovingSolids);
    o.tolerance_k = 1e-6;
    o.history_near_cells = near;
    FilmEnergySolver solver(g, oil, polymer, polymer, kT0, o);
    FilmTemperature t;
    const auto s = solver.Solve(f, nullptr, 0.0, &t);
    ASSERT_TRUE(s.usable()) << near << ": " << s.BriefReport();
    const double scale = t.MaxTemperature() - kT0;
    std::printf(
        "polymer solids, near band %d: %d steps, %d factorizations, %d GMRES iterations, "
        "T_max - T0 = %.3f K\n",
        near, s.iterations, s.factorizations, s.krylov_iterations, scale);
    const Eigen::VectorXd rise1 = src.Rise(polymer, c.u1_m_s, t.q1_w_m2);
    const Eigen::VectorXd rise2 = src.Rise(polymer, c.u2_m_s, t.q2_w_m2);
    EXPECT_LT((t.t1_k.array() - kT0 - rise1.array()).abs().maxCoeff(), 1e-6 * scale) << near;
    EXPECT_LT((t.t2_k.array() - kT0 - rise2.array()).abs().maxCoeff(), 1e-6 * scale) << near;
    EXPECT_LT(s.balance.RelativeError(), 0.01) << near;
    if (whole.size() == 0) whole = t.t_k;
    EXPECT_LT((t.t_k - whole).cwiseAbs().maxCoeff(), 10 * o.tolerance_k) << near;
  }
}

// Transient: a film with constant properties (beta = 0: linear) whose heating doubles at t = 0.
struct TransientCase {
  Lubricant oil = EnergyTestOil(0.0);
  UniformGrid g = UniformGrid::AroundHertz(1e-4, 65);
  EhlLikeParameters c = [] {
    EhlLikeParameters p;
    p.radius_m = 0.1;  // no reverse flow
    return p;
  }();
  FilmFlowField before = EhlLikeField(g, 11, oil, c);
  FilmFlowField after = [this] {
    FilmFlowField f = before;
    f.heating_w_m3 *= 2;
    return f;
  }();
  FilmEnergySolver solver{g,        oil, Bronze(),
                          Bronze(), kT0, Opts(11, FilmEnergySolver::Walls::kMovingSolids)};
  FilmTemperature Steady(const FilmFlowField& f) const {
    FilmTemperature t;
    EXPECT_TRUE(solver.Solve(f, nullptr, 0.0, &t).usable());
    return t;
  }
  FilmTemperature March(int steps, double t_end) const {
    FilmTemperature t = Steady(before), next;
    for (int k = 0; k < steps; ++k) {
      next = t;
      const auto s = solver.Solve(after, &t, t_end / steps, &next);
      EXPECT_TRUE(s.usable()) << s.BriefReport();
      EXPECT_LT(s.balance.RelativeError(), 0.01) << "step " << k;  // VALIDATION.md section 4
      t = next;
    }
    return t;
  }
};

TEST(FilmEnergySolver, StepInHeatingRelaxesToTheNewSteadyState) {
  // After many residence times (grid length 0.6 mm at >= 1 m/s: 0.6 ms) the implicit march
  // reaches the steady solution of the new heating.
  const TransientCase tc;
  const FilmTemperature steady = tc.Steady(tc.after);
  const FilmTemperature marched = tc.March(400, 0.02);
  const double diff = (marched.t_k - steady.t_k).cwiseAbs().maxCoeff();
  std::printf("marched vs steady: max |dT| = %.3e K (rise %.3f K)\n", diff,
              steady.MaxTemperature() - kT0);
  EXPECT_LT(diff, 1e-6);
}

TEST(FilmEnergySolver, ImplicitEulerIsFirstOrderInTime) {
  // The film relaxes by conduction to the surfaces in rho cp h^2/(pi^2 k): 0.3 us at h_c =
  // 0.5 um, 2 us in the 1.35 um inlet; the surfaces, which remember their heat history, like
  // half-spaces (sqrt(t)). March to t = 2 us with 10 ... 640 steps: once dt is below the
  // film's relaxation time (from 40 steps), successive differences halve (Richardson: e(dt) -
  // e(dt/2) = C dt/2 + O(dt^2)). 320 and 640 steps keep more levels than a FilmTemperature
  // holds (kMaxSolidFluxLevels): the merged history keeps the order.
  const TransientCase tc;
  std::vector<Eigen::MatrixXd> sol;
  for (int steps : {10, 20, 40, 80, 160, 320, 640}) sol.push_back(tc.March(steps, 2e-6).t_k);
  std::vector<double> d;
  for (size_t i = 1; i < sol.size(); ++i) d.push_back((sol[i] - sol[i - 1]).cwiseAbs().maxCoeff());
  for (size_t i = 1; i < d.size(); ++i) {
    const double order = std::log2(d[i - 1] / d[i]);
    std::printf("dt refinement %zu: difference %.3e K, order %.3f\n", i, d[i], order);
    if (i >= 3) {
      EXPECT_NEAR(order, 1.0, 0.1) << i;
    }
  }
}

TEST(FilmEnergySolver, SolidsKeepTheirHeatWhenTheHeatingStops) {
  // Steady heating, then none for one step of dt. A surface point at x has been heated for
  // about (x - x_0)/u (450 us at the hottest point, x - x_0 ~ 0.45 mm, u1 = 1 m/s) and cools
  // for dt: 1-D conduction into the half-space (Carslaw & Jaeger 1959, section 2.9) keeps
  // [sqrt(t_h + dt) - sqrt(dt)] / sqrt(t_h) of a uniform flux's rise: 0.985 after 0.1 us,
  // 0.956 after 1 us. Quasi-steady solids (each step's flux as if it had always acted) kept
  // 0.84 and 0.35 here: the film cools to the inlet temperature within a microsecond and its
  // wall flux turns toward the film.
  const TransientCase tc;
  const FilmTemperature hot = tc.Steady(tc.before);
  FilmFlowField off = tc.before;
  off.heating_w_m3.setZero();
  Eigen::Index hottest = 0;
  const double rise = hot.t1_k.maxCoeff(&hottest) - kT0;
  for (double dt : {1e-7, 1e-6}) {
    FilmTemperature next = hot;
    const auto s = tc.solver.Solve(off, &hot, dt, &next);
    ASSERT_TRUE(s.usable()) << s.BriefReport();
    const double kept = (next.t1_k[hottest] - kT0) / rise;
    const double t_h = (tc.g.x(hottest) - tc.g.x(0)) / tc.before.u1_m_s;
    const double one_d = (std::sqrt(t_h + dt) - std::sqrt(dt)) / std::sqrt(t_h);
    std::printf("dt %.0e s: surface 1 keeps %.4f of its %.2f K rise (1-D: %.4f)\n", dt, kept, rise,
                one_d);
    // The flux is not uniform along the path (measured 0.988, 0.927), and the film draws
    // heat back from the walls during the step: the surface cools by at least half the 1-D
    // drop (solids that kept all their heat would fail) and by at most 0.04 more than it
    // (quasi-steady solids, 0.84 and 0.35, would fail).
    EXPECT_LT(kept, 1 - 0.5 * (1 - one_d));
    EXPECT_GT(kept, one_d - 0.04);
  }
}

TEST(FilmEnergySolver, ReusedFactorizationGivesTheSameTemperaturesAsAFreshOne) {
  // The coupling loop of the pressure solver re-solves a changed flow with the factorization
  // kept from the last call (chord steps): the answer must be the fresh solve's, to the
  // tolerance (1e-6 K here), whether the flow changed a little (heating +1 %) or a lot
  // (sliding reversed: u1 = 1.5, u2 = 1 m/s).
  const Lubricant oil = EnergyTestOil();
  const UniformGrid g = UniformGrid::AroundHertz(1e-4, 257);
  FilmEnergySolver::Options o = Opts(11, FilmEnergySolver::Walls::kMovingSolids);
  o.tolerance_k = 1e-6;
  const FilmFlowField first = EhlLikeField(g, 11, oil, EhlLikeParameters{});
  FilmFlowField hotter = first;
  hotter.heating_w_m3 *= 1.01;
  EhlLikeParameters swapped;
  swapped.u1_m_s = 1.5;
  swapped.u2_m_s = 1.0;
  const FilmFlowField reversed_sliding = EhlLikeField(g, 11, oil, swapped);
  for (const FilmFlowField* next :
       {static_cast<const FilmFlowField*>(&hotter), &reversed_sliding}) {
    FilmEnergySolver reused(g, oil, Bronze(), Bronze(), kT0, o);
    FilmTemperature t;
    ASSERT_TRUE(reused.Solve(first, nullptr, 0.0, &t).usable());
    const auto warm = reused.Solve(*next, nullptr, 0.0, &t);
    ASSERT_TRUE(warm.usable()) << warm.BriefReport();
    FilmEnergySolver fresh(g, oil, Bronze(), Bronze(), kT0, o);
    FilmTemperature u;
    ASSERT_TRUE(fresh.Solve(*next, nullptr, 0.0, &u).usable());
    std::printf("warm re-solve: %d steps, %d factorizations; max |T_warm - T_fresh| = %.2e K\n",
                warm.iterations, warm.factorizations, (t.t_k - u.t_k).cwiseAbs().maxCoeff());
    EXPECT_LT((t.t_k - u.t_k).cwiseAbs().maxCoeff(), 2e-6);
    EXPECT_LT((t.q1_w_m2 - u.q1_w_m2).cwiseAbs().maxCoeff(),
              1e-6 * u.q1_w_m2.cwiseAbs().maxCoeff());
  }
}

TEST(FilmEnergySolver, ALooserToleranceStopsEarlierAndStaysWithinIt) {
  // The coupling loop passes its own, looser tolerance while its iterate still moves (inexact
  // solves). Contract: fewer Picard steps, and the answer within that tolerance of the tight
  // solve (rho(T) with expansivity 6.5e-4 1/K makes the problem nonlinear).
  EhlLikeParameters c;
  const Lubricant oil = EnergyTestOil(6.5e-4);
  const UniformGrid g = UniformGrid::AroundHertz(c.half_width_m, 129);
  const FilmFlowField f = EhlLikeField(g, 11, oil, c);
  const FilmEnergySolver::Options o = Opts(11, FilmEnergySolver::Walls::kMovingSolids);
  FilmEnergySolver tight(g, oil, Bronze(), Bronze(), kT0, o);
  FilmTemperature t_ref;
  const auto ref = tight.Solve(f, nullptr, 0.0, &t_ref);
  ASSERT_TRUE(ref.usable()) << ref.BriefReport();
  ASSERT_GT(t_ref.MaxTemperature() - kT0, 1.0);  // a warm film, so 0.05 K is a real cut
  FilmEnergySolver loose(g, oil, Bronze(), Bronze(), kT0, o);
  FilmTemperature t;
  const double tolerance_k = 0.05;
  const auto s = loose.Solve(f, nullptr, 0.0, tolerance_k, &t);
  ASSERT_TRUE(s.usable()) << s.BriefReport();
  EXPECT_LT(s.iterations, ref.iterations);
  EXPECT_LT((t.t_k - t_ref.t_k).cwiseAbs().maxCoeff(), tolerance_k);
  EXPECT_THROW(loose.Solve(f, nullptr, 0.0, 0.0, &t), InputError);
}

TEST(FilmEnergySolver, PicardLimitIsReportedNotThrown) {
  EhlLikeParameters c;
  const Lubricant oil = EnergyTestOil(6.5e-4);
  const UniformGrid g = UniformGrid::AroundHertz(c.half_width_m, 65);
  FilmEnergySolver::Options o = Opts(11, FilmEnergySolver::Walls::kMovingSolids);
  o.max_iterations = 1;
  FilmEnergySolver solver(g, oil, Bronze(), Bronze(), kT0, o);
  FilmTemperature t;
  const auto s = solver.Solve(EhlLikeField(g, 11, oil, c), nullptr, 0.0, &t);
  EXPECT_EQ(s.termination, FilmEnergySolver::Termination::kMaxIterations);
  EXPECT_NE(s.message.find("Picard"), std::string::npos) << s.message;
  EXPECT_TRUE(t.t_k.allFinite());
}

TEST(FilmEnergySolverOptions, RejectsEveryBadField) {
  FilmEnergySolver::Options o;
  EXPECT_TRUE(o.Validate().empty());
  o.film_nodes = 2;
  o.tolerance_k = 0;
  o.max_iterations = 0;
  o.relaxation = 1.5;
  o.history_near_cells = -1;
  EXPECT_EQ(o.Validate().size(), 5u);
  const Lubricant oil = EnergyTestOil();
  const UniformGrid g(0.0, 1e-3, 11);
  EXPECT_THROW(FilmEnergySolver(g, oil, Bronze(), Bronze(), kT0, o), InputError);
  EXPECT_THROW(FilmEnergySolver(g, oil, Bronze(), Bronze(), -1.0, FilmEnergySolver::Options{}),
               InputError);
  EXPECT_THROW(FilmEnergySolver(g, oil, SolidThermal{}, Bronze(), kT0, FilmEnergySolver::Options{}),
               InputError);
}

TEST(FilmEnergySolver, RejectsAMalformedFlowField) {
  const Lubricant oil = EnergyTestOil();
  const UniformGrid g = UniformGrid::AroundHertz(1e-4, 33);
  FilmEnergySolver solver(g, oil, Bronze(), Bronze(), kT0, FilmEnergySolver::Options{});
  const FilmFlowField good = EhlLikeField(g, 11, oil, EhlLikeParameters{});
  FilmTemperature t;
  auto expect_key = [&](FilmFlowField f, const std::string& key, const FilmTemperature* prev,
                        double dt) {
    try {
      solver.Solve(f, prev, dt, &t);
      ADD_FAILURE() << "no InputError for " << key;
    } catch (const InputError& e) {
      EXPECT_EQ(e.problems().front().key, key) << e.what();
    }
  };
  FilmFlowField f = good;
  f.u1_m_s = 0;
  expect_key(f, "FilmFlowField::u1_m_s", nullptr, 0);
  f = good;
  f.h_m[3] = -1e-9;
  expect_key(f, "FilmFlowField::h_m", nullptr, 0);
  f = good;
  f.u_m_s.resize(33, 10);
  expect_key(f, "FilmFlowField::u_m_s", nullptr, 0);
  f = good;
  f.heating_w_m3(2, 2) = NAN;
  expect_key(f, "FilmFlowField::heating_w_m3", nullptr, 0);
  expect_key(good, "previous", nullptr, 1e-6);
}

}  // namespace
}  // namespace tehl

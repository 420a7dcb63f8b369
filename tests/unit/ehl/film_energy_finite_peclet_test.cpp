// The film energy equation with finite-Peclet surface temperatures (FilmEnergySolver::Options::
// finite_peclet, Jaeger's moving line source; include/tehl/ehl/surface_temperature.hpp): the
// converged surfaces satisfy the whole kernel (the upstream part is lagged by the iteration,
// the fixed point must not be), the energy balance of VALIDATION.md section 4 still closes, and
// at a high Peclet number the film is that of the high-Peclet form of seed 004 eqs. (14)-(15).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/test_lubricants.hpp"
#include "tehl/ehl/film_energy.hpp"
#include "unit/ehl/film_flow_fields.hpp"

namespace tehl {
namespace {

using testing::Bronze;
using testing::EhlLikeField;
using testing::EhlLikeParameters;
using testing::EnergyTestOil;

constexpr double kT0 = testing::kReferenceT0;

struct Solved {
  FilmTemperature t;
  FilmEnergySolver::Summary summary;
};

Solved SolveFilm(const UniformGrid& g,
                 const FilmFlowField& f,
                 const SolidThermal& solid,
                 bool finite_peclet) {
  FilmEnergySolver::Options o;
  o.tolerance_k = 1e-7;
  o.finite_peclet = finite_peclet;
  static const Lubricant oil = EnergyTestOil();
  const FilmEnergySolver solver(g, oil, solid, solid, kT0, o);
  Solved s;
  s.summary = solver.Solve(f, nullptr, 0.0, &s.t);
  return s;
}

// The seed 004 contact at A has Peclet numbers u b / (2 kappa) of 1.3 (pinion) and 2.8
// (wheel) (docs/thermal.md); here slow bronze surfaces, u1 = 0.3 and u2 = 0.6 m/s under a
// b = 0.1 mm film: Pe = 0.81 and 1.6, with reverse flow in the inlet. Also polymer-like solids
// (effusivity sqrt(k rho c) 1/19 of bronze's, kappa = 1.4e-7 m^2/s) at 1 and 2 mm/s, Pe 0.35
// and 0.70, strongly coupled to a 0.1 um film: there the heat conducted ahead is many times
// the part of the kernel kept in the factorized matrix, and lagging it in chord steps
// diverged (the reason for the Krylov steps of FilmEnergySystem::Correction).
TEST(FilmEnergyFinitePeclet, SurfacesSatisfyTheWholeKernelAndTheBalanceCloses) {
  struct Case {
    const char* name;
    SolidThermal solid;
    double u1, u2, film_m;
  };
  const Case cases[] = {
      {"bronze", Bronze(), 0.3, 0.6, 0.5e-6},
      {"polymer", SolidThermal{1300.0, 1340.0, 0.25}, 1e-3, 2e-3, 1e-7},
  };
  for (const Case& c : cases) {
    EhlLikeParameters p;
    p.u1_m_s = c.u1;
    p.u2_m_s = c.u2;
    p.central_film_m = c.film_m;
    p.eta0_pa_s = c.u1 < 0.01 ? 50.0 : 0.05;  // keep the heating of the slow polymer case
    const Lubricant oil = EnergyTestOil();
    const UniformGrid g = UniformGrid::AroundHertz(p.half_width_m, 257);
    const FilmFlowField f = EhlLikeField(g, 11, oil, p);
    const Solved fin = SolveFilm(g, f, c.solid, true);
    ASSERT_TRUE(fin.summary.usable()) << c.name << ": " << fin.summary.BriefReport();
    const Solved high = SolveFilm(g, f, c.solid, false);
    ASSERT_TRUE(high.summary.usable()) << c.name << ": " << high.summary.BriefReport();
    const double w1 = MovingHeatSource::DecayRate(c.solid, c.u1);
    const double w2 = MovingHeatSource::DecayRate(c.solid, c.u2);
    const Eigen::VectorXd rise1 = MovingHeatSource(g, w1).Rise(c.solid, c.u1, fin.t.q1_w_m2);
    const Eigen::VectorXd rise2 = MovingHeatSource(g, w2).Rise(c.solid, c.u2, fin.t.q2_w_m2);
    const double scale = fin.t.MaxTemperature() - kT0;
    const double surf1 = fin.t.t1_k.maxCoeff() - kT0, surf1_high = high.t.t1_k.maxCoeff() - kT0;
    std::printf(
        "%s: Pe %.2f, %.2f; %d steps, %d factorizations, %d GMRES iterations; T_max - T0 %.3f "
        "K (high-Peclet form %.3f K); surface 1 max rise %.3f K (%.3f K); surface 1 at the "
        "inlet %.2e K\n",
        c.name, w1 * p.half_width_m, w2 * p.half_width_m, fin.summary.iterations,
        fin.summary.factorizations, fin.summary.krylov_iterations, scale,
        high.t.MaxTemperature() - kT0, surf1, surf1_high, fin.t.t1_k[0] - kT0);
    // The fixed point: T_s - T0 = F sum_k G_ik q_k over every cell, ahead of x_i too.
    EXPECT_LT((fin.t.t1_k.array() - kT0 - rise1.array()).abs().maxCoeff(), 1e-5 * scale) << c.name;
    EXPECT_LT((fin.t.t2_k.array() - kT0 - rise2.array()).abs().maxCoeff(), 1e-5 * scale) << c.name;
    EXPECT_LT(fin.summary.balance.RelativeError(), 0.01) << c.name;  // VALIDATION.md section 4
    // Conduction along the surface spreads the heat: a lower peak than the high-Peclet form,
    // whose surface at the inlet end stays at T0.
    EXPECT_LT(surf1, surf1_high) << c.name;
    EXPECT_EQ(high.t.t1_k[0], kT0) << c.name;
    EXPECT_GT(fin.summary.krylov_iterations, 0) << c.name;
  }
}

TEST(FilmEnergyFinitePeclet, AtAHighPecletNumberTheFilmIsThatOfTheHighPecletForm) {
  // A solid with bronze's effusivity sqrt(k rho c) (the same factor F, the same high-Peclet
  // film) but a diffusivity 10^4 times smaller: Pe = 8100 at 1 m/s. The finite-Peclet film
  // must agree with the high-Peclet one to O(1/sqrt(Pe)) of the rise, the size of the heat
  // conducted ahead within one cell.
  const SolidThermal bronze = Bronze();
  const SolidThermal slow{bronze.density_kg_m3 * 100, bronze.heat_capacity_j_kgk,
                          bronze.conductivity_w_mk / 100};
  EhlLikeParameters p;
  const Lubricant oil = EnergyTestOil();
  const UniformGrid g = UniformGrid::AroundHertz(p.half_width_m, 257);
  const FilmFlowField f = EhlLikeField(g, 11, oil, p);
  const Solved fin = SolveFilm(g, f, slow, true), high = SolveFilm(g, f, slow, false);
  ASSERT_TRUE(fin.summary.usable()) << fin.summary.BriefReport();
  ASSERT_TRUE(high.summary.usable()) << high.summary.BriefReport();
  const double pe = MovingHeatSource::DecayRate(slow, p.u1_m_s) * p.half_width_m;
  const double scale = high.t.MaxTemperature() - kT0;
  const double diff = (fin.t.t_k - high.t.t_k).cwiseAbs().maxCoeff();
  std::printf("Pe %.0f: T_max - T0 %.4f K, largest difference %.2e K (%.2e of the rise)\n", pe,
              scale, diff, diff / scale);
  EXPECT_GT(pe, 5000);
  EXPECT_LT(diff, scale / std::sqrt(pe));
}

}  // namespace
}  // namespace tehl

// Re-solves on a kept energy system (FilmEnergySolver::Options::reuse_factorization), as the
// thermal coupling loop of the pressure solver does: a film that changes a little between
// Solves. Where the lagged far history stalls the chord steps (solids strongly coupled to the
// film), the first Solve switches to Krylov steps; the later Solves on the same system must
// start with them instead of rediscovering the stall with fresh factorizations and diverging
// chord steps, and must still give the film's own temperatures.
#include <gtest/gtest.h>

#include <cstdio>

#include "support/test_lubricants.hpp"
#include "tehl/ehl/film_energy.hpp"
#include "tehl/ehl/surface_temperature.hpp"
#include "unit/ehl/film_flow_fields.hpp"

namespace tehl {
namespace {

constexpr double kT0 = testing::kReferenceT0;

// Polymer-like solids under a 0.1 um film (testing::ThinEhlFilm): the history lagged outside
// the factorized matrix stalls the chord steps.
const SolidThermal kPolymer = testing::Polymer();

FilmEnergySolver::Options Options() {
  FilmEnergySolver::Options o;
  o.film_nodes = 11;
  o.tolerance_k = 1e-6;
  return o;
}

TEST(FilmEnergyResolve, ALaterSolveOfAStronglyCoupledFilmStartsWithKrylovSteps) {
  const testing::ThinEhlFilm film;
  const MovingHeatSource src(film.g);
  FilmEnergySolver kept(film.g, film.oil, kPolymer, kPolymer, kT0, Options());
  FilmTemperature t;
  const auto first = kept.Solve(film.f, nullptr, 0.0, &t);
  ASSERT_TRUE(first.usable()) << first.BriefReport();
  // The first Solve found the stall: it took GMRES steps, after at least two factorizations
  // of the full matrix (the rule of FilmEnergySolver::Solve).
  ASSERT_GT(first.krylov_iterations, 0);
  ASSERT_GE(first.factorizations, 2);
  for (double scale : {1.01, 1.03, 0.98}) {
    FilmFlowField hotter = film.f;
    hotter.heating_w_m3 *= scale;
    const auto again = kept.Solve(hotter, nullptr, 0.0, &t);
    ASSERT_TRUE(again.usable()) << scale << ": " << again.BriefReport();
    std::printf("heating x %.2f: %d steps, %d factorizations, %d GMRES iterations\n", scale,
                again.iterations, again.factorizations, again.krylov_iterations);
    // Krylov steps from the first step on: at most one fresh factorization (when the kept one
    // has aged), against at least two before the first Krylov step when the stall is found
    // again.
    EXPECT_GT(again.krylov_iterations, 0) << scale;
    EXPECT_LE(again.factorizations, 1) << scale;
    // The answer is the film's own: a fresh solver on the same film agrees to ten times the
    // tolerance, and the surfaces satisfy the whole history (the O(n^2) moving-heat-source sums
    // of their fluxes) to 1e-6 of the rise.
    FilmEnergySolver fresh(film.g, film.oil, kPolymer, kPolymer, kT0, Options());
    FilmTemperature u;
    ASSERT_TRUE(fresh.Solve(hotter, nullptr, 0.0, &u).usable()) << scale;
    EXPECT_LT((t.t_k - u.t_k).cwiseAbs().maxCoeff(), 10 * Options().tolerance_k) << scale;
    const double rise = t.MaxTemperature() - kT0;
    const Eigen::VectorXd rise1 = src.Rise(kPolymer, film.c.u1_m_s, t.q1_w_m2);
    const Eigen::VectorXd rise2 = src.Rise(kPolymer, film.c.u2_m_s, t.q2_w_m2);
    EXPECT_LT((t.t1_k.array() - kT0 - rise1.array()).abs().maxCoeff(), 1e-6 * rise) << scale;
    EXPECT_LT((t.t2_k.array() - kT0 - rise2.array()).abs().maxCoeff(), 1e-6 * rise) << scale;
  }
}

}  // namespace
}  // namespace tehl

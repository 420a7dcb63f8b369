// Hard cases of the isothermal EHL line contact (VALIDATION.md section 3: "points above
// 2.5 GPa are beyond the regime of the fits ... they must converge or stop with a diagnostic,
// never return NaN"). Each run either converges or returns usable() == false with a message;
// in both cases the returned state is finite everywhere and p >= 0 (the Reynolds cavitation
// condition). Invalid conditions are reported as kInvalidInput, never thrown, never NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <type_traits>

#include "verification/ehl_moes_point.hpp"

namespace tehl {
namespace {

using testing::MoesPoint;
using testing::MoesSolver;

// must_converge: a point documented to converge (docs/validation.md) must, not only return a
// diagnosed failure.
void ExpectConvergedOrDiagnosed(const MoesPoint& mp, int n, bool must_converge = false) {
  MoesSolver ms(mp, n);
  FilmState st;
  LineContactSolver::Summary sum;
  ASSERT_NO_THROW(sum = ms.solver.SolveSteady(mp.Conditions(), &st));
  std::printf("M = %g, L = %g, p_H = %.3g GPa, n = %d: %s; H_c = %.5g, H_min = %.5g, "
              "p_max/p_H = %.4f\n",
              mp.M, mp.L, mp.Hertz().max_pressure_pa / 1e9, n, sum.BriefReport().c_str(),
              ms.Hc(st), ms.Hmin(st), st.MaxPressure() / mp.Hertz().max_pressure_pa);
  if (must_converge) EXPECT_TRUE(sum.usable()) << sum.BriefReport();
  if (!sum.usable()) {
    EXPECT_FALSE(sum.message.empty());
  }
  // A converged film carries the whole load (the load row is part of the residual).
  if (sum.usable()) {
    EXPECT_LT(sum.load_error, 1e-8);
  }
  ASSERT_TRUE(st.valid());
  EXPECT_EQ(st.p_pa.size(), n);
  EXPECT_TRUE(st.p_pa.allFinite());
  EXPECT_TRUE(st.h_m.allFinite());
  EXPECT_TRUE(std::isfinite(st.h0_m));
  EXPECT_GE(st.p_pa.minCoeff(), 0.0);
  EXPECT_TRUE(std::isfinite(sum.residual));
}

TEST(HardCasesVerification, VeryHighLoadAndPiezoviscosityM5000L25) {
  // p_H = 31 GPa (VALIDATION.md section 1 groups): far beyond any real lubricant.
  ExpectConvergedOrDiagnosed(MoesPoint{5000, 25}, 513);
}

// M = 1000, L = 2 does not converge on 513 nodes (docs/validation.md section 3.1): the grid
// spans the Hertzian edge of the film (include/tehl/ehl/hertz_edge.hpp) with about half a
// cell. The diagnostic says so and names the grid that spans 10 cells: 16385 nodes, where the
// film is within 0.21 % of the grid-converged one (docs/validation.md section 3.2).
TEST(HardCasesVerification, AFailedSolveOnAGridThatMissesTheHertzianEdgeSaysSo) {
  const MoesPoint mp{1000, 2};
  MoesSolver ms(mp, 513);
  FilmState st;
  const LineContactSolver::Summary sum = ms.solver.SolveSteady(mp.Conditions(), &st);
  ASSERT_FALSE(sum.usable());
  EXPECT_NE(sum.message.find("the grid spans the Hertzian edge of the film"), std::string::npos)
      << sum.message;
  EXPECT_NE(sum.message.find("about 16385 nodes would span it"), std::string::npos) << sum.message;
}

TEST(HardCasesVerification, NearlyIsoviscousL1) {
  // L = 1: almost no piezoviscosity, slow entrainment, p_H = 80 MPa. Converges (3 Newton
  // iterations).
  ExpectConvergedOrDiagnosed(MoesPoint{20, 1}, 513, /*must_converge=*/true);
}

TEST(HardCasesVerification, SteelAtFourGigapascal) {
  // VALIDATION.md section 3 table point M = 500, L = 10: p_H = 3.99 GPa.
  const MoesPoint mp{500, 10};
  EXPECT_NEAR(mp.Hertz().max_pressure_pa / 1e9, 3.99, 0.005);
  // A table point of docs/validation.md section 3, which converges (6 Newton iterations).
  ExpectConvergedOrDiagnosed(mp, 513, /*must_converge=*/true);
}

// Continuation raises the load from 5 % in stages. A run whose stages end below the full
// load must not report convergence: its film carries only part of the load. (It once did:
// M = 1000, L = 2 on 2049 nodes returned "converged" with p_max = 0.27 p_H after 12 stages.)
TEST(HardCasesVerification, ContinuationThatEndsBelowTheFullLoadIsNotConverged) {
  const MoesPoint mp{1000, 2};  // p_H = 1.13 GPa; on 1025 nodes it needs 6 stages
  LineContactSolver::Options opt;
  opt.max_continuation_stages = 3;  // 0.05, 0.1, 0.2 of the load
  MoesSolver ms(mp, 1025, opt);
  FilmState st;
  const auto sum = ms.solver.SolveSteady(mp.Conditions(), &st);
  std::printf("%s\n", sum.BriefReport().c_str());
  EXPECT_FALSE(sum.usable());
  EXPECT_GT(sum.load_error, 0.5);  // the state solves 0.2 of the load at most
  EXPECT_NE(sum.message.find("of the load"), std::string::npos) << sum.message;
  EXPECT_TRUE(st.p_pa.allFinite());
  EXPECT_GE(st.p_pa.minCoeff(), 0.0);
}

TEST(HardCasesVerification, InvalidConditionsAreReportedNotThrown) {
  const MoesPoint mp{20, 10};
  MoesSolver ms(mp, 257);
  const ContactConditions good = mp.Conditions();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Bad {
    const char* what;
    ContactConditions c;
  };
  std::vector<Bad> cases;
  for (double r : {0.0, -0.01, nan}) cases.push_back({"R", {r, good.u1_m_s, good.u2_m_s,
                                                            good.load_n_per_m, good.temperature_k}});
  for (double u : {0.0, -1.0, nan}) cases.push_back({"um", {good.reduced_radius_m, u, u,
                                                             good.load_n_per_m, good.temperature_k}});
  for (double w : {0.0, -1e5, nan}) cases.push_back({"w", {good.reduced_radius_m, good.u1_m_s,
                                                            good.u2_m_s, w, good.temperature_k}});
  // 40 "K" is 40 degrees Celsius given as kelvin, and no oil is at 5000 K (units.hpp:
  // kMinAbsoluteTemperatureK, kMaxTemperatureK).
  for (double t : {40.0, 0.0, 5000.0, nan})
    cases.push_back({"T", {good.reduced_radius_m, good.u1_m_s, good.u2_m_s, good.load_n_per_m, t}});
  for (const Bad& b : cases) {
    // From an empty state and from a valid starting guess: neither may gain a NaN.
    for (bool with_guess : {false, true}) {
      FilmState st;
      if (with_guess) st = ms.solver.InitialGuess(good);
      const FilmState before = st;
      LineContactSolver::Summary sum;
      ASSERT_NO_THROW(sum = ms.solver.SolveSteady(b.c, &st)) << b.what;
      EXPECT_EQ(sum.termination, LineContactSolver::Termination::kInvalidInput) << b.what;
      EXPECT_FALSE(sum.usable());
      EXPECT_NE(sum.message.find("invalid"), std::string::npos) << sum.message;
      EXPECT_TRUE(st.p_pa.allFinite() && st.h_m.allFinite()) << b.what;
      EXPECT_EQ(st.p_pa.size(), before.p_pa.size());
      if (with_guess) {
        EXPECT_EQ((st.p_pa - before.p_pa).cwiseAbs().maxCoeff(), 0.0);
      }
      // The friction of what is left: the guess's, or NaN for the empty state (no read past
      // its end: a mesh cycle records the friction of every step, failed or not).
      const FilmFriction f = ms.solver.Friction(good, st);
      if (with_guess)
        EXPECT_TRUE(std::isfinite(f.coefficient)) << b.what;
      else
        EXPECT_TRUE(std::isnan(f.coefficient)) << b.what;
    }
  }
}

// A film state that is not of the solver's grid, or no state at all, is an invalid input:
// reported in the Summary (SolveSteady, Step) or thrown as InputError (BeginTransient), never
// read past its end. An empty state is a cold start for SolveSteady only.
TEST(HardCasesVerification, AStateOfAnotherGridOrNoneIsReportedNotRead) {
  const MoesPoint mp{20, 10};
  MoesSolver ms(mp, 257, {}, /*transient=*/true);
  MoesSolver coarse(mp, 129, {}, /*transient=*/true);
  const ContactConditions c = mp.Conditions();
  using T = LineContactSolver::Termination;
  EXPECT_EQ(ms.solver.SolveSteady(c, nullptr).termination, T::kInvalidInput);
  EXPECT_EQ(ms.solver.Step(c, 1e-6, nullptr).termination, T::kInvalidInput);
  FilmState empty;
  const LineContactSolver::Summary never_solved = ms.solver.Step(c, 1e-6, &empty);
  EXPECT_EQ(never_solved.termination, T::kInvalidInput);
  EXPECT_NE(never_solved.message.find("SolveSteady first"), std::string::npos)
      << never_solved.message;
  EXPECT_THROW(ms.solver.BeginTransient(c, empty), InputError);
  FilmState other;
  ASSERT_TRUE(coarse.solver.SolveSteady(c, &other).usable());
  const LineContactSolver::Summary wrong = ms.solver.SolveSteady(c, &other);
  EXPECT_EQ(wrong.termination, T::kInvalidInput);
  EXPECT_NE(wrong.message.find("129 pressures"), std::string::npos) << wrong.message;
  EXPECT_EQ(ms.solver.Step(c, 1e-6, &other).termination, T::kInvalidInput);
  EXPECT_THROW(ms.solver.BeginTransient(c, other), InputError);
  EXPECT_TRUE(std::isnan(ms.solver.ResidualNorm(c, other)));
  EXPECT_EQ(ms.solver.MassFlow(c, other).size(), 0);
  EXPECT_EQ(other.p_pa.size(), 129);  // untouched
  // The same steps from a state of its own grid work: cold steady, then a transient step.
  FilmState own;
  ASSERT_TRUE(ms.solver.SolveSteady(c, &own).usable());
  EXPECT_TRUE(ms.solver.Step(c, 1e-6, &own).usable());
}

// Settings that would be silently ignored or crash later are refused when the solver is
// made: a coarse grid below 5 nodes, an enum value outside its type, finite_peclet without
// the thermal film, roughness with both surfaces smooth, a non-finite E', an empty grid.
TEST(HardCasesVerification, SettingsThatWouldBeIgnoredAreRefusedAtConstruction) {
  const MoesPoint mp{20, 10};
  const UniformGrid grid = mp.Grid(129);
  const Lubricant oil = testing::ReferenceOil(mp.eta0_pa_s, mp.z);
  const auto make = [&](const FilmEffects& e, const LineContactSolver::Options& o, double e_prime) {
    LineContactSolver s(grid, e_prime, oil, e, o);
  };
  const FilmEffects plain;
  LineContactSolver::Options coarse;
  coarse.coarse_grid_nodes = 0;
  EXPECT_THROW(make(plain, coarse, mp.e_prime_pa), InputError);
  LineContactSolver::Options solver;
  solver.linear_solver = static_cast<LinearSolverKind>(42);
  EXPECT_THROW(make(plain, solver, mp.e_prime_pa), InputError);
  LineContactSolver::Options scheme;
  scheme.time_scheme = static_cast<TimeScheme>(7);
  EXPECT_THROW(make(plain, scheme, mp.e_prime_pa), InputError);
  FilmEffects peclet;
  peclet.finite_peclet = true;
  EXPECT_THROW(make(peclet, {}, mp.e_prime_pa), InputError);
  FilmEffects rough;
  rough.roughness = true;
  EXPECT_THROW(make(rough, {}, mp.e_prime_pa), InputError);
  EXPECT_THROW(make(plain, {}, std::numeric_limits<double>::infinity()), InputError);
  EXPECT_NO_THROW(make(plain, {}, mp.e_prime_pa));
  try {
    make(plain, coarse, mp.e_prime_pa);
    ADD_FAILURE() << "coarse_grid_nodes = 0 was accepted";
  } catch (const InputError& e) {
    // The option's own key, its value and what is allowed (not the struct's name twice).
    ASSERT_EQ(e.problems().size(), 1u) << e.what();
    EXPECT_EQ(e.problems()[0].key, "LineContactSolver::Options::coarse_grid_nodes");
    EXPECT_EQ(e.problems()[0].value, "0");
    EXPECT_EQ(e.problems()[0].allowed, ">= 5");
  }
  // An empty (default-constructed) grid, with or without the elastic deflection (without it
  // the solve used to crash).
  for (bool elastic : {false, true}) {
    FilmEffects e;
    e.elastic = elastic;
    try {
      const UniformGrid empty;
      LineContactSolver s(empty, mp.e_prime_pa, oil, e, LineContactSolver::Options{});
      ADD_FAILURE() << "an empty grid was accepted, elastic " << elastic;
    } catch (const InputError& err) {
      EXPECT_EQ(err.problems()[0].key, "grid") << err.what();
    }
  }
}

// A grid sized for 1/2.25 of the load (2/3 of the Hertz half-width b) ends inside the film of
// the full load: -4.5 b .. 1.5 b of the smaller contact reaches 1.0 b of the larger, short of
// its Reynolds exit past b. The converged film says so (Summary::outlet_cut); on its own grid
// it does not.
TEST(HardCasesVerification, AGridThatEndsInsideTheFilmIsReported) {
  const MoesPoint mp{20, 10};
  MoesSolver ms(mp, 257);
  ContactConditions c = mp.Conditions();
  FilmState own;
  const LineContactSolver::Summary fits = ms.solver.SolveSteady(c, &own);
  ASSERT_TRUE(fits.usable()) << fits.BriefReport();
  EXPECT_FALSE(fits.outlet_cut);
  c.load_n_per_m *= 2.25;
  FilmState cut;
  const LineContactSolver::Summary s = ms.solver.SolveSteady(c, &cut);
  ASSERT_TRUE(s.usable()) << s.BriefReport();
  EXPECT_TRUE(s.outlet_cut);
  EXPECT_NE(s.BriefReport().find("cuts the film off"), std::string::npos) << s.BriefReport();
}

// The lubricant must outlive the solver: a temporary one is refused at compile time.
static_assert(!std::is_constructible_v<LineContactSolver,
                                       const UniformGrid&,
                                       double,
                                       Lubricant&&,
                                       const FilmEffects&,
                                       const LineContactSolver::Options&>);
static_assert(std::is_constructible_v<LineContactSolver,
                                      const UniformGrid&,
                                      double,
                                      const Lubricant&,
                                      const FilmEffects&,
                                      const LineContactSolver::Options&>);

}  // namespace
}  // namespace tehl

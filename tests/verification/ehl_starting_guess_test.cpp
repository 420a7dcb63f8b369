// Independence of the steady EHL solution from the starting guess (VALIDATION.md section 3:
// "independence from the starting guess is what proves it right"). The discrete problem has
// one solution; Newton's method started from InitialGuess (Hertz pressure, h0 from the Moes
// fit) with the rigid approach h0 scaled by 0.8, 1.0 and 1.2 must end at the same film to the
// solver tolerance: the central and minimum films agree to 1e-6 relative. The guess's h0
// carries the constant of the log-kernel deflection (about -50 Moes films at M = 20, L = 10),
// so the scalings shift the starting film by about +-10 central films: 1.2 starts from a
// negative film, which the solver first lifts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "tehl/ehl/surface_roughness.hpp"
#include "verification/ehl_moes_point.hpp"

namespace tehl {
namespace {

using testing::MoesPoint;
using testing::MoesSolver;

void ExpectSameFilmFromEveryStart(int n) {
  const MoesPoint mp{20, 10};  // VALIDATION.md section 3 table point, p_H = 0.80 GPa
  const ContactConditions c = mp.Conditions();
  double hc[3], hmin[3];
  const double factors[3] = {0.8, 1.0, 1.2};
  for (int k = 0; k < 3; ++k) {
    MoesSolver ms(mp, n);
    FilmState st = ms.solver.InitialGuess(c);
    const double h0_guess = st.h0_m;
    st.h0_m *= factors[k];  // the solver recomputes h from p and h0
    const LineContactSolver::Summary sum = ms.solver.SolveSteady(c, &st);
    ASSERT_TRUE(sum.usable()) << "h0 x " << factors[k] << ": " << sum.BriefReport();
    hc[k] = ms.Hc(st);
    hmin[k] = ms.Hmin(st);
    // The shift of the starting film, (f - 1) h0, in units of the Moes central film.
    std::printf("n = %d, h0 x %.1f (film shifted by %+.3f h_c,Moes): H_c = %.10f "
                "H_min = %.10f (%s)\n",
                n, factors[k], (factors[k] - 1.0) * h0_guess / (mp.MoesHc() * mp.FilmScale()),
                hc[k], hmin[k], sum.BriefReport().c_str());
  }
  for (int k : {0, 2}) {
    EXPECT_NEAR(hc[k] / hc[1], 1.0, 1e-6) << "n = " << n << ", h0 x " << factors[k];
    EXPECT_NEAR(hmin[k] / hmin[1], 1.0, 1e-6) << "n = " << n << ", h0 x " << factors[k];
  }
}

TEST(StartingGuessVerification, SameFilmFromPerturbedApproachOn257Nodes) {
  ExpectSameFilmFromEveryStart(257);
}

TEST(StartingGuessVerification, SameFilmFromPerturbedApproachOn513Nodes) {
  ExpectSameFilmFromEveryStart(513);
}

// A state without a film (a cold solve) still carries its time and the travel of both
// surfaces: the fresh guesses that replace it (grid sequencing, and the load continuation's
// Hertz guess) keep them, so rough surfaces are sampled where they are. Surface 1 carries
// waviness of 0.3 central films and wavelength b/2, moved by d = 0.3 wavelengths; the same
// film must come out of the surface with its phase shifted by 2 pi d / wavelength at travel 0
// (SinusoidalWaviness: height(x, d) = A sin(2 pi (x - d) / wavelength + phase)).
TEST(StartingGuessVerification, AColdSolveSamplesRoughSurfacesAtTheStateTravel) {
  const MoesPoint mp{20, 10};
  const ContactConditions c = mp.Conditions();
  const double a = 0.3 * mp.MoesHc() * mp.FilmScale();
  const double lambda = 0.5 * mp.Hertz().half_width_m, d = 0.3 * lambda;
  FilmEffects effects;
  effects.transient = false;
  effects.roughness = true;
  const LineContactSolver::Options o;
  const Lubricant oil = testing::ReferenceOil(mp.eta0_pa_s);  // outlives the solvers
  auto film = [&](double phase, double travel) {
    LineContactSolver solver(mp.Grid(257), mp.e_prime_pa, oil, effects, o,
                             std::make_shared<SinusoidalWaviness>(a, lambda, phase));
    FilmState st;
    st.time_s = 2e-4;
    st.travel1_m = travel;
    st.travel2_m = 2 * travel;
    const LineContactSolver::Summary sum = solver.SolveSteady(c, &st);
    EXPECT_TRUE(sum.usable()) << sum.BriefReport();
    EXPECT_EQ(st.time_s, 2e-4);
    EXPECT_EQ(st.travel1_m, travel);
    EXPECT_EQ(st.travel2_m, 2 * travel);
    std::printf("phase %.3f, travel %.3g m: h_min %.6e m, %s\n", phase, travel, st.MinFilm(),
                sum.BriefReport().c_str());
    return st;
  };
  const double kPi = 3.14159265358979323846;
  const FilmState moved = film(0.0, d);
  const FilmState shifted = film(-2 * kPi * d / lambda, 0.0);
  EXPECT_NEAR(moved.MinFilm() / shifted.MinFilm(), 1.0, 1e-6);
  EXPECT_NEAR(moved.MaxPressure() / shifted.MaxPressure(), 1.0, 1e-6);
  // Not the film of travel 0: the waviness moves h_min by more than the tolerance.
  EXPECT_GT(std::abs(film(0.0, 0.0).MinFilm() / moved.MinFilm() - 1.0), 1e-3);
}

}  // namespace
}  // namespace tehl

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

}  // namespace
}  // namespace tehl

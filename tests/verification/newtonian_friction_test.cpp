// Friction of the isothermal Newtonian film (seed 004 eq. 16) against the wall stresses of
// the Couette-Poiseuille profile, integrated here from the solved film alone. With eta(p, T0)
// uniform across the film, u(z) = u1 + (u2 - u1) z/h + p' (z^2 - z h)/(2 eta), the stress on
// surface 1 is tau(0) = eta (u2 - u1)/h - h p'/2 and on surface 2 -tau(h) = -eta (u2 - u1)/h
// - h p'/2. With C = int eta (u2 - u1)/h dx and P = int (h/2) p' dx = -(1/2) int p h' dx
// (p = 0 at both ends):
//   F1 = C - P,  F2 = -C - P,  mu = (|F1| + |F2|) / (2 w) = max(|C|, |P|) / w.
// Sliding films are Couette-dominated (C), rolling ones are all P.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "tehl/lubricant/lubricant.hpp"
#include "verification/thermal_disc_case.hpp"

namespace tehl {
namespace {

using testing::DiscSolver;
using testing::Sae40;
using testing::ThermalDisc;

struct Integrals {
  double couette = 0, poiseuille = 0;  // C and P above [N/m]
};

// Trapezoid sums over the solved film; h' by central differences (one-sided at the ends,
// where p = 0 makes their terms vanish).
Integrals FromFilm(const FilmState& s, const ContactConditions& c, double dx) {
  Integrals r;
  const int n = static_cast<int>(s.p_pa.size());
  for (int i = 0; i < n; ++i) {
    const double w = (i == 0 || i == n - 1) ? 0.5 * dx : dx;
    const double p = std::max(s.p_pa[i], 0.0);
    const double eta = Sae40().viscosity().Evaluate(p, c.temperature_k).eta_pa_s;
    r.couette += w * eta * (c.u2_m_s - c.u1_m_s) / s.h_m[i];
    const double dh = i == 0       ? (s.h_m[1] - s.h_m[0]) / dx
                      : i == n - 1 ? (s.h_m[n - 1] - s.h_m[n - 2]) / dx
                                   : (s.h_m[i + 1] - s.h_m[i - 1]) / (2 * dx);
    r.poiseuille -= 0.5 * w * p * dh;
  }
  return r;
}

TEST(NewtonianFriction, EachSurfacesForceIsTheCouettePoiseuilleIntegral) {
  for (const auto& [um, srr] :
       {std::pair{1.0, 0.0}, std::pair{1.0, 0.2}, std::pair{2.0, 0.5}, std::pair{0.5, -0.3}}) {
    ThermalDisc d;
    d.um_m_s = um;
    d.srr = srr;
    const ContactConditions c = d.Conditions(Sae40());
    LineContactSolver solver = DiscSolver(d, Sae40(), 513, /*thermal=*/false);
    FilmState s;
    ASSERT_TRUE(solver.SolveSteady(c, &s).usable()) << "um " << um << " SRR " << srr;
    const Integrals want = FromFilm(s, c, solver.grid().dx_m());
    const FilmFriction f = solver.Friction(c, s);
    const double scale = std::max(std::abs(want.couette), std::abs(want.poiseuille));
    std::printf("um %.1f SRR %+.1f: C %.6g, P %.6g N/m; F1 %.6g, F2 %.6g N/m, mu %.5g\n", um, srr,
                want.couette, want.poiseuille, f.traction1_n_per_m, f.traction2_n_per_m,
                f.coefficient);
    // Both are trapezoid sums; P from h' by parts equals P from p' (the solver's central
    // differences) by discrete summation by parts, p being 0 at both ends: to round-off.
    EXPECT_NEAR(f.traction1_n_per_m, want.couette - want.poiseuille, 1e-9 * scale)
        << "um " << um << " SRR " << srr;
    EXPECT_NEAR(f.traction2_n_per_m, -want.couette - want.poiseuille, 1e-9 * scale)
        << "um " << um << " SRR " << srr;
    EXPECT_NEAR(f.coefficient, scale / c.load_n_per_m, 1e-9 * scale / c.load_n_per_m)
        << "um " << um << " SRR " << srr;
    if (srr != 0.0) {
      EXPECT_GT(std::abs(want.couette), 10 * std::abs(want.poiseuille));  // Couette-dominated
      // The mean of the two surfaces is the Couette term alone, to round-off.
      EXPECT_NEAR(0.5 * (f.traction1_n_per_m - f.traction2_n_per_m), want.couette,
                  1e-9 * std::abs(want.couette));
    }
  }
}

}  // namespace
}  // namespace tehl

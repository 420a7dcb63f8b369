// The involute function and its inverse.
#include "tehl/gear/involute.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tehl/units.hpp"

namespace tehl {
namespace {

TEST(Involute, MatchesSeed000AppendixTable) {
  // Seed 000 appendix "Table of involute functions", spot values (extraction section 7.2 V1),
  // printed to 6 decimals.
  const double deg[] = {20, 25, 30, 35, 40};
  const double table[] = {0.014904, 0.029975, 0.053751, 0.089342, 0.140968};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(Involute(DegToRad(deg[i])), table[i], 5e-7) << deg[i];
}

TEST(Involute, CorrectsTheMisprintedTableEntries) {
  // Seed 000 extraction section 2.3: five printed entries are wrong; the recomputed values.
  EXPECT_NEAR(Involute(DegToRad(27.1)), 0.038742, 5e-7);
  EXPECT_NEAR(Involute(DegToRad(34.1)), 0.081894, 5e-7);
}

TEST(InverseInvolute, RoundTripsOverTheWholeRange) {
  for (double deg = 0.01; deg < 89.0; deg += 0.37) {
    const double phi = DegToRad(deg);
    EXPECT_NEAR(InverseInvolute(Involute(phi)), phi, 1e-13 * std::max(1.0, phi)) << deg;
  }
  EXPECT_EQ(InverseInvolute(0.0), 0.0);
}

TEST(InverseInvolute, RejectsNegativeValues) {
  EXPECT_THROW(InverseInvolute(-1e-3), std::domain_error);
}

TEST(Involute, DerivativeIsTanSquaredByCentralDifference) {
  // d inv(phi)/dphi = sec^2(phi) - 1 = tan^2(phi), used by the Newton solvers.
  for (double deg : {10.0, 20.0, 35.0, 50.0}) {
    const double phi = DegToRad(deg), h = 1e-6;
    const double fd = (Involute(phi + h) - Involute(phi - h)) / (2 * h);
    EXPECT_NEAR(fd, std::pow(std::tan(phi), 2), 1e-8);
  }
}

TEST(ProfileAngleAtRadius, IsThePressureAngleAtThePitchCircle) {
  // Seed 000 eq. 2.9: cos(phi) = r_b / r; at the pitch circle of a 20 deg gear, 20 deg.
  const double r = 0.035, rb = r * std::cos(DegToRad(20));
  EXPECT_NEAR(ProfileAngleAtRadius(rb, r), DegToRad(20), 1e-14);
  EXPECT_NEAR(RollDistance(rb, r), rb * std::tan(DegToRad(20)), 1e-16);
}

}  // namespace
}  // namespace tehl

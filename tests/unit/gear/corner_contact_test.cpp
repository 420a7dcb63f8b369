// Corner contact beyond A and E (src/gear/corner_contact.cpp): the separation of a tip
// corner from the mating flank against the shortest distance from the corner to that flank's
// involute, found by direct search along the involute (independent of the roll-length
// formula), for an external and an internal pair.
#include "tehl/gear/corner_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "unit/gear/reference_pairs.hpp"

namespace tehl {
namespace {

struct P {
  double x, y;
};
P Rot(P v, double a) {
  return {std::cos(a) * v.x - std::sin(a) * v.y, std::sin(a) * v.x + std::cos(a) * v.y};
}

// Point of roll length l on the involute of base circle rb (centre c) that crosses the
// tangent line at the top of the circle, y = c.y + rb, at x = c.x + u0 (the string leaves
// its tangent point clockwise), turned by `turn` about c.
P InvolutePoint(P c, double rb, double u0, double l, double turn) {
  const double g = 0.5 * M_PI + (l - u0) / rb;
  const P q = Rot({rb * std::cos(g) + l * std::sin(g), rb * std::sin(g) - l * std::cos(g)}, turn);
  return {c.x + q.x, c.y + q.y};
}

// Shortest distance from q to that involute: a scan over l, then golden-section refinement.
double DistanceToInvolute(P q, P c, double rb, double u0, double turn) {
  auto d = [&](double l) {
    const P p = InvolutePoint(c, rb, u0, l, turn);
    return std::hypot(p.x - q.x, p.y - q.y);
  };
  const double r = std::hypot(q.x - c.x, q.y - c.y);
  const double l_hi = 2 * std::sqrt(r * r - rb * rb) + 10 * rb;
  double best = 0;
  for (int i = 0; i <= 20000; ++i) {
    const double l = l_hi * i / 20000;
    if (d(l) < d(best)) best = l;
  }
  double a = std::max(0.0, best - l_hi / 20000), b = best + l_hi / 20000;
  const double k = 0.5 * (std::sqrt(5.0) - 1);
  for (int i = 0; i < 200; ++i) {
    const double m1 = b - k * (b - a), m2 = a + k * (b - a);
    (d(m1) < d(m2) ? b : a) = (d(m1) < d(m2) ? m2 : m1);
  }
  return d(0.5 * (a + b));
}

void ExpectSeparationsAreDistances(const GearPairSpec& spec) {
  const GearPair pair(spec);
  const LineOfAction& l = pair.line(Flank::kDrive);
  const bool ring = spec.internal;
  const double rb1 = l.pinion_base_radius_m, rb2 = l.wheel_base_radius_m, lt = l.tangent_length_m;
  const double g = l.length_m, ra = l.a_m;
  const CornerContact corner(pair, Flank::kDrive, 1e-4);
  ASSERT_GT(corner.before_m(), 0.0);
  ASSERT_GT(corner.after_m(), 0.0);
  EXPECT_EQ(corner.GapAt(0.0), 0.0);
  EXPECT_EQ(corner.GapAt(0.5 * g), 0.0);
  EXPECT_EQ(corner.GapAt(g), 0.0);
  const P o1{0, 0}, o2 = ring ? P{-lt, rb1 - rb2} : P{lt, rb1 + rb2};
  for (double f : {0.1, 0.3, 0.6, 0.9}) {
    // Before A: the wheel's corner (at A when s = 0) turned back; the pinion's flank is the
    // involute crossing the line at rho_A + s.
    const double s = -f * corner.before_m();
    const P a{ra - o2.x, rb1 - o2.y};
    const P wr = Rot(a, (ring ? -1.0 : 1.0) * s / rb2);
    const P q{o2.x + wr.x, o2.y + wr.y};
    const double d_a = DistanceToInvolute(q, o1, rb1, ra + s, 0.0);
    EXPECT_NEAR(corner.GapAt(s), d_a, 1e-9 + 1e-6 * d_a) << "before A, s = " << s;
    // After E: the pinion's corner turned on; the wheel's flank crosses the line at rho_A + s,
    // i.e. at roll length T1T2 - (rho_A + s) from T2 (external: the wheel's involutes turned by
    // pi) or T1T2 + rho_A + s (ring).
    const double t = g + f * corner.after_m();
    const P e = Rot({ra + g, rb1}, -(t - g) / rb1);
    const double d_e = ring ? DistanceToInvolute(e, o2, rb2, lt + ra + t, 0.0)
                            : DistanceToInvolute(e, o2, rb2, lt - (ra + t), M_PI);
    EXPECT_NEAR(corner.GapAt(t), d_e, 1e-9 + 1e-6 * d_e) << "after E, s = " << t;
  }
  // The separation grows from zero about quadratically (the corner leaves a smooth flank).
  const double h = 1e-3 * corner.before_m();
  EXPECT_NEAR(corner.GapAt(-2 * h) / corner.GapAt(-h), 4.0, 0.05);
  const double k = 1e-3 * corner.after_m();
  EXPECT_NEAR(corner.GapAt(g + 2 * k) / corner.GapAt(g + k), 4.0, 0.05);
  // Beyond the extension nothing touches.
  EXPECT_TRUE(std::isinf(corner.GapAt(-1.01 * corner.before_m())));
  EXPECT_TRUE(std::isinf(corner.GapAt(g + 1.01 * corner.after_m())));
}

TEST(CornerContact, SeparationIsTheDistanceToTheMatingInvoluteExternal) {
  ExpectSeparationsAreDistances(testing::Seed004Spec());
}

TEST(CornerContact, SeparationIsTheDistanceToTheMatingInvoluteInternal) {
  ExpectSeparationsAreDistances(testing::InternalSpec());
}

TEST(CornerContact, ExtensionEndsAtTheLargestSeparation) {
  // Seed 004: the pinion's form circle (33.454 mm) lies below the point the wheel's corner
  // touches within 0.1 mm of separation, so the extension ends at the separation itself.
  const GearPair pair(testing::Seed004Spec());
  for (double cap : {2e-5, 1e-4}) {
    const CornerContact c(pair, Flank::kDrive, cap);
    EXPECT_NEAR(c.GapAt(-c.before_m()), cap, 1e-9 * cap);
    EXPECT_NEAR(c.GapAt(pair.line(Flank::kDrive).length_m + c.after_m()), cap, 1e-9 * cap);
  }
}

}  // namespace
}  // namespace tehl

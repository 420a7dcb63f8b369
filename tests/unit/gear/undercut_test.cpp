// Where the involute of an undercut gear begins (undercut.hpp): against a brute-force test of
// the rack tooth reaching into the involute, for sharp and rounded rack tips; its limits; and
// the interference check that uses it.
#include "tehl/gear/undercut.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "tehl/gear/gear_pair.hpp"
#include "tehl/gear/geometry_checks.hpp"
#include "tehl/gear/involute.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {

RackCut Rack(int z, double x, double rho_fp = 0.38) {
  RackCut c;
  c.module_m = 2e-3;
  c.pitch_radius_m = z * c.module_m / 2;
  c.pressure_angle_rad = 20 * kPi / 180;
  c.profile_shift = x;
  c.dedendum_coefficient = 1.25;
  c.root_fillet_coefficient = rho_fp;
  return c;
}

// By brute force: does the rack tooth reach into the involute point at roll s from T, at any
// turn of the gear? The gear's frame at rotation 0: pitch point P0 = (0, r); the involute
// through P0 in polar form theta(R) = inv(acos(r_b / R)) - inv(alpha) from P0's direction
// (classical involute geometry). The rack tooth at rotation phi (moved by r phi): flank
// through P0 at alpha from the normal, tip line h_fP m below the reference line y = r + x m,
// corner rounded by rho = rho_fP m (the points within rho of the tooth shrunk by rho). A gear
// point q is inside when it lies in that rounded tooth after the turn.
bool RackReaches(const RackCut& c, double s) {
  const double r = c.pitch_radius_m, a = c.pressure_angle_rad, rb = r * std::cos(a);
  const double rho = c.root_fillet_coefficient * c.module_m;
  const double radius = std::hypot(rb, s);
  const double theta = Involute(std::acos(rb / radius)) - Involute(a);
  const double qu = radius * std::sin(theta), qy = radius * std::cos(theta);
  const double y_tip = r + (c.profile_shift - c.dedendum_coefficient) * c.module_m;
  const double cy = y_tip + rho, cu = (cy - r) * std::tan(a) - rho / std::cos(a);
  const double span = std::max(0.6, 6 * c.module_m / r);
  for (int k = -200000; k <= 200000; ++k) {
    const double phi = span * k / 200000;
    // The point seen from the rack: turned with the gear, shifted by the rack's travel.
    const double u = std::cos(phi) * qu - std::sin(phi) * qy + r * phi - cu;
    const double y = std::sin(phi) * qu + std::cos(phi) * qy - cy;
    const double below = -y, beyond = u * std::cos(a) - y * std::sin(a);
    if (below < -1e-9 && beyond < -1e-9) return true;  // inside the shrunk tooth
    // Distance to the shrunk tooth: to the nearer of its edges (rays from its corner).
    double d = 1e9;
    for (const auto& [tu, ty] : {std::pair{-1.0, 0.0}, std::pair{std::sin(a), std::cos(a)}}) {
      const double t = std::max(0.0, u * tu + y * ty);
      d = std::min(d, std::hypot(u - t * tu, y - t * ty));
    }
    if (d < rho - 1e-9) return true;
  }
  return false;
}

TEST(Undercut, TheRackReachesTheInvoluteBelowTheLimitAndNotAbove) {
  int checked = 0;
  for (double rho : {0.0, 0.38})
    for (int z : {8, 10, 12, 14})
      for (double x : {-0.2, 0.0, 0.2}) {
        const RackCut c = Rack(z, x, rho);
        const double s_u = UndercutRollLength(c);
        const double h0 = 1.25 - rho * (1 - std::sin(c.pressure_angle_rad));
        const bool undercut = x < h0 - z * std::pow(std::sin(c.pressure_angle_rad), 2) / 2;
        EXPECT_EQ(s_u > 0, undercut) << "z " << z << " x " << x << " rho " << rho;
        if (!undercut) continue;
        const double delta = 0.005 * s_u;  // the brute force resolves depths of 1 nm
        EXPECT_TRUE(RackReaches(c, s_u - delta)) << "z " << z << " x " << x << " rho " << rho;
        EXPECT_FALSE(RackReaches(c, s_u + delta)) << "z " << z << " x " << x << " rho " << rho;
        ++checked;
      }
  EXPECT_GE(checked, 15);
}

TEST(Undercut, NoneWithoutUndercutAndItVanishesAtTheLimit) {
  // ISO 53 rack: x_min = h_F0 - z sin^2(alpha) / 2, h_F0 = 1.25 - 0.38 (1 - sin 20 deg).
  const double h0 = 1.25 - 0.38 * (1 - std::sin(20 * kPi / 180));
  const double sin2 = std::pow(std::sin(20 * kPi / 180), 2);
  EXPECT_EQ(UndercutRollLength(Rack(18, 0.0)), 0.0);
  EXPECT_EQ(UndercutRollLength(Rack(12, h0 - 6 * sin2 + 1e-6)), 0.0);
  // Just below the limit the cut is small, and it grows as the shift falls.
  const double near = UndercutRollLength(Rack(12, h0 - 6 * sin2 - 1e-3));
  EXPECT_GT(near, 0.0);
  EXPECT_LT(near, 0.05 * 2e-3);
  double last = near;
  for (double x : {0.2, 0.1, 0.0, -0.1}) {
    const double s = UndercutRollLength(Rack(12, x));
    EXPECT_GT(s, last) << "x " << x;
    last = s;
  }
}

TEST(Undercut, TheFilletCutsLessThanTheSharpCorner) {
  // The rounded tip lies inside the sharp one: it removes less of the involute.
  for (int z : {10, 12, 14}) {
    const double sharp = UndercutRollLength(Rack(z, 0.0, 0.0));
    const double round = UndercutRollLength(Rack(z, 0.0, 0.38));
    EXPECT_GT(round, 0.0) << z;
    EXPECT_LT(round, sharp) << z;
  }
}

// A 12-tooth pinion (x = 0, undercut) made with allow_undercut: its involute begins above the
// base circle, and a wheel tip that meets it below that is interference, not a contact at the
// base circle (where R -> 0).
TEST(Undercut, AMatingTipMustMeetTheInvoluteThatIsLeft) {
  GearPairSpec s;
  s.module_m = 2e-3;
  s.face_width_m = 0.02;
  s.pinion.teeth = 12;
  s.wheel.teeth = 60;
  s.allow_undercut = true;
  s.drive_pressure_angle_rad = s.coast_pressure_angle_rad = 20 * kPi / 180;
  s.wheel.tip_radius_m = 61.5247e-3;  // crosses the line of action at T1
  const GearPair at_t1(s);
  const FlankGeometry& f = at_t1.pinion().flank(Flank::kDrive);
  ASSERT_TRUE(f.undercut);
  EXPECT_GT(f.form_radius_m, f.base_radius_m + 1e-5);
  bool refused = false;
  for (const GeometryProblem& p : CheckGeometry(at_t1))
    refused = refused || (!p.warning && p.rule.find("undercut") != std::string::npos);
  EXPECT_TRUE(refused);
  // A wheel tip of 61.0 mm starts the path 1.1 mm from T1, above the cut (0.77 mm).
  s.wheel.tip_radius_m = 61.0e-3;
  const GearPair clear(s);
  ASSERT_GT(
      std::hypot(clear.line(Flank::kDrive).pinion_base_radius_m, clear.line(Flank::kDrive).a_m),
      f.form_radius_m);
  for (const GeometryProblem& p : CheckGeometry(clear)) EXPECT_TRUE(p.warning) << p.ToString();
}

}  // namespace
}  // namespace tehl

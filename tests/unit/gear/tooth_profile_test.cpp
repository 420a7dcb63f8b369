// Tooth profile points: involute flanks, trochoidal root fillets, tip and root arcs.
#include "tehl/gear/tooth_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tehl/gear/involute.hpp"
#include "unit/gear/reference_pairs.hpp"

namespace tehl {
namespace {

const ProfileCurve& Find(const std::vector<ProfileCurve>& c,
                         const std::string& gear,
                         const std::string& flank) {
  for (const auto& x : c)
    if (x.gear == gear && x.flank == flank) return x;
  throw std::runtime_error("no curve " + gear + " " + flank);
}

double Radius(const ProfilePoint& p) { return std::hypot(p.x_m, p.y_m); }
double AngleFromY(const ProfilePoint& p) { return std::atan2(p.x_m, p.y_m); }

TEST(ToothProfile, InvoluteFlanksFollowThePolarInvoluteEquation) {
  // Seed 000 eqs. 2.11-2.12: along one involute the polar angle changes by
  // inv(phi(r1)) - inv(phi(r2)) between radii r1 and r2 (cos phi = r_b / r); and at the tip
  // both flanks end at r_a, an angle s_a / r_a apart (eq. 2.13, one involute per flank).
  // Asymmetric 35/20 pinion of seed 000.
  const GearPair pair(testing::Seed000Spec(35, 20));
  ToothProfileOptions o;
  o.fillet_points = 30;
  const auto curves = ToothProfile(pair, o);
  const GearGeometry& g = pair.pinion();
  const int n = o.involute_points;
  for (const Flank f : {Flank::kDrive, Flank::kCoast}) {
    const auto& c = Find(curves, "pinion", ToString(f));
    const double sign = f == Flank::kDrive ? 1 : -1;  // coast flank on the -x side
    const ProfilePoint& top = c.points.back();
    const double rb = g.flank(f).base_radius_m;
    for (int i = 0; i < n; ++i) {
      const ProfilePoint& p = c.points[c.points.size() - n + i];
      const double d_angle = sign * (AngleFromY(p) - AngleFromY(top));
      EXPECT_NEAR(d_angle,
                  Involute(std::acos(rb / Radius(top))) - Involute(std::acos(rb / Radius(p))),
                  1e-13);
    }
    EXPECT_NEAR(Radius(top), g.tip_radius_m, 1e-15);
  }
  const ProfilePoint& d = Find(curves, "pinion", "drive").points.back();
  const ProfilePoint& c = Find(curves, "pinion", "coast").points.back();
  EXPECT_NEAR(AngleFromY(d) - AngleFromY(c), g.tip_thickness_m / g.tip_radius_m, 1e-13);
}

TEST(ToothProfile, FilletRunsFromTheRootCircleToTheInvoluteFormCircle) {
  // The trochoid of the rack tip rounding starts on the root circle (rack tip line) and
  // joins the involute at the form circle with the same point (envelope of the rack).
  GearPairSpec s = testing::FzgCSpec();
  const GearPair pair(s);
  ToothProfileOptions o;
  const auto curves = ToothProfile(pair, o);
  for (const char* gear : {"pinion", "wheel"}) {
    const GearGeometry& g = std::string(gear) == "pinion" ? pair.pinion() : pair.wheel();
    const auto& drive = Find(curves, gear, "drive");
    EXPECT_NEAR(Radius(drive.points.front()), g.root_radius_m, 1e-12) << gear;
    const ProfilePoint& fillet_end = drive.points[o.fillet_points - 1];
    const ProfilePoint& involute_start = drive.points[o.fillet_points];
    EXPECT_NEAR(Radius(fillet_end), g.drive.form_radius_m, 1e-12) << gear;
    EXPECT_NEAR(fillet_end.x_m, involute_start.x_m, 1e-12) << gear;
    EXPECT_NEAR(fillet_end.y_m, involute_start.y_m, 1e-12) << gear;
    for (const auto& p : drive.points) {
      EXPECT_GE(Radius(p), g.root_radius_m - 1e-12);
      EXPECT_LE(Radius(p), g.tip_radius_m + 1e-12);
    }
    // Symmetric teeth: the coast flank mirrors the drive flank.
    const auto& coast = Find(curves, gear, "coast");
    for (size_t i = 0; i < drive.points.size(); ++i) {
      EXPECT_NEAR(coast.points[i].x_m, -drive.points[i].x_m, 1e-15);
      EXPECT_NEAR(coast.points[i].y_m, drive.points[i].y_m, 1e-15);
    }
    EXPECT_NO_THROW(Find(curves, gear, "tip"));
    EXPECT_NO_THROW(Find(curves, gear, "root"));
  }
}

TEST(ToothProfile, RingFlanksSpanTipToRoot) {
  const GearPairSpec s = testing::InternalSpec();
  const GearPair pair(s);
  const auto curves = ToothProfile(pair);
  const auto& drive = Find(curves, "wheel", "drive");
  EXPECT_NEAR(Radius(drive.points.front()), 0.088, 1e-15);
  EXPECT_NEAR(Radius(drive.points.back()), pair.wheel().root_radius_m, 1e-15);
  // The space between the two flanks of the ring at radius r is 2 pi r / z - s_tooth(r).
  const auto& coast = Find(curves, "wheel", "coast");
  const double r = Radius(drive.points[10]);
  EXPECT_NEAR(AngleFromY(drive.points[10]) - AngleFromY(coast.points[10]),
              2 * kPi / 60 - pair.wheel().ThicknessAtRadius(r) / r, 1e-12);
}

}  // namespace
}  // namespace tehl

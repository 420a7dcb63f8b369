// The coast side of a pair (src/gear/flank_phase.cpp): the mirrored pair's drive line is the
// coast line, and the coast contacts the pinion's rotation places (CoastPhaseOffset) are
// checked against those the wheel's rotation places, computed here from the wheel's own
// teeth: at zero backlash both flanks of the mesh touch at once, so the two must agree; with
// backlash j on the working pitch circle they differ by the coast gap j cos(alpha_wc), that
// is j / p_w pitches (docs/dynamics.md "Back flanks").
#include "tehl/gear/flank_phase.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tehl/gear/involute.hpp"
#include "unit/gear/reference_pairs.hpp"

namespace tehl {
namespace {

double Wrap(double q) { return q - std::round(q); }  // to [-1/2, 1/2]

// The wheel's side of the derivation in flank_phase.hpp: its crossings u2 are measured from
// T2 towards T1, u2 = T1T2 - T1A - s, and the same identity holds for its teeth.
double WheelCoastPhaseOffset(const GearPair& pair) {
  const GearGeometry& w = pair.wheel();
  const LineOfAction& d = pair.line(Flank::kDrive);
  const LineOfAction& c = pair.line(Flank::kCoast);
  const double theta_b = w.reference_thickness_m / w.pitch_radius_m +
                         Involute(w.drive.pressure_angle_rad) +
                         Involute(w.coast.pressure_angle_rad);
  return (d.tangent_length_m - d.a_m) / d.base_pitch_m +
         (c.tangent_length_m - c.a_m) / c.base_pitch_m -
         w.teeth * (theta_b + d.working_pressure_angle_rad + c.working_pressure_angle_rad) /
             (2.0 * kPi);
}

double WorkingPitch(const GearPair& pair) {
  const double z1 = pair.pinion().teeth, z2 = pair.wheel().teeth;
  return 2.0 * kPi * pair.center_distance_m() / (z1 + z2);  // 2 pi r_w1 / z1
}

GearPairSpec Shifted(GearPairSpec s, double x1, double x2) {
  s.pinion.profile_shift = x1;
  s.wheel.profile_shift = x2;
  return s;
}

TEST(CoastSide, MirroredPairsDriveLineIsTheCoastLine) {
  for (const GearPairSpec& s : {testing::Seed000Spec(35, 20), testing::Seed000Spec(20, 35),
                                Shifted(testing::Seed000Spec(30, 20), 0.2, -0.1)}) {
    const GearPair pair(s), mirrored(CoastSideSpec(s));
    const LineOfAction& c = pair.line(Flank::kCoast);
    const LineOfAction& m = mirrored.line(Flank::kDrive);
    EXPECT_DOUBLE_EQ(m.pinion_base_radius_m, c.pinion_base_radius_m);
    EXPECT_DOUBLE_EQ(m.wheel_base_radius_m, c.wheel_base_radius_m);
    EXPECT_NEAR(m.a_m, c.a_m, 1e-12);
    EXPECT_NEAR(m.length_m, c.length_m, 1e-12);
    EXPECT_NEAR(m.c_m, c.c_m, 1e-12);
    EXPECT_NEAR(mirrored.center_distance_m(), pair.center_distance_m(), 1e-12);
    EXPECT_NEAR(mirrored.backlash_m(), pair.backlash_m(), 1e-12);
  }
}

TEST(CoastPhaseOffset, PinionAndWheelPlaceTheCoastContactsAlikeAtZeroBacklash) {
  for (const GearPairSpec& s :
       {testing::Seed004Spec(), testing::Seed000Spec(35, 20), testing::Seed000Spec(20, 35),
        Shifted(testing::Seed000Spec(30, 20), 0.3, -0.2),
        Shifted(testing::Seed004Spec(), 0.4, 0.1)}) {
    const GearPair pair(s);
    ASSERT_NEAR(pair.backlash_m(), 0.0, 1e-12);
    const double delta = CoastPhaseOffset(pair);
    EXPECT_GE(delta, 0.0);
    EXPECT_LT(delta, 1.0);
    EXPECT_NEAR(Wrap(delta - WheelCoastPhaseOffset(pair)), 0.0, 1e-9);
  }
}

TEST(CoastPhaseOffset, WithBacklashTheWheelLagsByTheCoastGap) {
  for (double extra_m : {20e-6, 100e-6, 400e-6}) {
    GearPairSpec s = testing::Seed000Spec(35, 20);
    s.center_distance_m = GearPair(s).center_distance_m() + extra_m;
    const GearPair pair(s);
    ASSERT_GT(pair.backlash_m(), 0.0);
    const double gap = pair.backlash_m() / WorkingPitch(pair);
    EXPECT_NEAR(std::abs(Wrap(CoastPhaseOffset(pair) - WheelCoastPhaseOffset(pair))), gap, 1e-9)
        << "centre distance +" << extra_m;
  }
}

// Symmetric teeth: by mirror symmetry about the line of centres a tooth whose axis lies on
// it has its drive and coast crossings at the same s, s_C + r_b1 s_w1 / (2 r_w1); so
// s_c + s_d = 2 s_C + s_w1 p_b / p_w for every tooth.
TEST(CoastPhaseOffset, SymmetricTeethFollowMirrorSymmetry) {
  for (const GearPairSpec& s :
       {testing::Seed004Spec(), Shifted(testing::Seed004Spec(), 0.4, 0.1), testing::FzgCSpec()}) {
    const GearPair pair(s);
    const LineOfAction& d = pair.line(Flank::kDrive);
    const double rw1 =
        pair.center_distance_m() * pair.pinion().teeth / (pair.pinion().teeth + pair.wheel().teeth);
    const double s_w1 = pair.pinion().ThicknessAtRadius(rw1);
    const double s_c = d.c_m - d.a_m;  // the pitch point on the path (C is from T1)
    const double expected = 2.0 * s_c / d.base_pitch_m + s_w1 / WorkingPitch(pair);
    EXPECT_NEAR(Wrap(CoastPhaseOffset(pair) - expected), 0.0, 1e-9);
  }
}

// Plane geometry, independent of the roll-length identity of flank_phase.hpp: the pinion's
// two flanks built by unwinding a string from each base circle (through the reference
// circle at the ends of the arc thickness s = m (pi/2 + x (tan a_d + tan a_c))), the lines of
// action as the tangents from the pitch point, A and A_c where the wheel's tip circle meets
// them, and the crossings of the turning flanks with the lines found by bisection. The pinion
// turns clockwise (its drive flank on the side of smaller polar angle leads); the drive line
// touches the drive base circle at polar angle pi/2 + a_wd, the coast line the coast one at
// pi/2 - a_wc.
struct V2 {
  double x, y;
};
V2 Dir(double a) { return {std::cos(a), std::sin(a)}; }
double Cross(V2 a, V2 b) { return a.x * b.y - a.y * b.x; }

struct PlaneMesh {
  explicit PlaneMesh(const GearPair& pair) {
    const GearPairSpec& sp = pair.spec();
    z1 = pair.pinion().teeth;
    const double z2 = pair.wheel().teeth, m = sp.module_m, r = 0.5 * z1 * m;
    const double a = pair.center_distance_m();
    const double rw = sp.internal ? a * z1 / (z2 - z1) : a * z1 / (z2 + z1);
    ra1 = pair.pinion().tip_radius_m;
    ra2 = pair.wheel().tip_radius_m;
    o2 = {0, sp.internal ? -a : a};
    const double s =
        m * (0.5 * kPi + pair.pinion().profile_shift * (std::tan(sp.drive_pressure_angle_rad) +
                                                        std::tan(sp.coast_pressure_angle_rad)));
    for (int f = 0; f < 2; ++f) {
      const double alpha = f == 0 ? sp.drive_pressure_angle_rad : sp.coast_pressure_angle_rad;
      rb[f] = r * std::cos(alpha);
      const double aw = std::acos(rb[f] / rw);
      const double tangent = f == 0 ? 0.5 * kPi + aw : 0.5 * kPi - aw;
      t1[f] = {rb[f] * std::cos(tangent), rb[f] * std::sin(tangent)};
      dir[f] = {-t1[f].y / rb[f] * (f == 0 ? -1 : 1), t1[f].x / rb[f] * (f == 0 ? -1 : 1)};
      // From T1 towards the pitch point P = (0, r_w).
      if ((0 - t1[f].x) * dir[f].x + (rw - t1[f].y) * dir[f].y < 0) dir[f] = {-dir[f].x, -dir[f].y};
      const double u_p = (0 - t1[f].x) * dir[f].x + (rw - t1[f].y) * dir[f].y;
      // A: the wheel's tip circle on the line, the crossing nearest below P.
      const V2 w{t1[f].x - o2.x, t1[f].y - o2.y};
      const double b = w.x * dir[f].x + w.y * dir[f].y, c = w.x * w.x + w.y * w.y - ra2 * ra2;
      const double root = std::sqrt(b * b - c);
      a_m[f] = -b + root < u_p ? -b + root : -b - root;
      pitch[f] = 2 * kPi * rb[f] / z1;
      // Base point of the flank through the reference circle at polar angle 0 (drive) or s/r
      // (coast): the string's roll t_r there, the point's angle t_r - atan(t_r) from it.
      const double tr = std::sqrt(r * r / (rb[f] * rb[f]) - 1);
      beta[f] = f == 0 ? std::atan(tr) - tr : s / r + tr - std::atan(tr);
    }
  }
  // Point of flank f (0 drive, 1 coast) of tooth k at roll t, the pinion turned clockwise by
  // psi.
  V2 Flank(int f, int k, double t, double psi) const {
    const double turn = -psi + 2 * kPi * k / z1;
    const double tau = f == 0 ? beta[f] + t + turn : beta[f] - t + turn;
    const V2 e = Dir(tau);
    const V2 along = f == 0 ? V2{e.y, -e.x} : V2{-e.y, e.x};  // the string, unwound away
    return {rb[f] * e.x + rb[f] * t * along.x, rb[f] * e.y + rb[f] * t * along.y};
  }
  // Path coordinate from A of a crossing of flank f with its line, any tooth; NaN: none.
  double Crossing(int f, double psi) const {
    const double t_tip = std::sqrt(ra1 * ra1 / (rb[f] * rb[f]) - 1);
    for (int k = 0; k < z1; ++k) {
      const auto side = [&](double t) {
        const V2 q = Flank(f, k, t, psi);
        return Cross(dir[f], {q.x - t1[f].x, q.y - t1[f].y});
      };
      double lo = 0, hi = t_tip;
      if ((side(lo) > 0) == (side(hi) > 0)) continue;
      for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        ((side(mid) > 0) == (side(lo) > 0) ? lo : hi) = mid;
      }
      const V2 q = Flank(f, k, lo, psi);
      const double u = (q.x - t1[f].x) * dir[f].x + (q.y - t1[f].y) * dir[f].y;
      if (u > 0) return u - a_m[f];
    }
    return std::nan("");
  }
  int z1 = 0;
  double ra1 = 0, ra2 = 0, rb[2] = {}, a_m[2] = {}, pitch[2] = {}, beta[2] = {};
  V2 o2{}, t1[2]{}, dir[2]{};
};

TEST(CoastPhaseOffset, MatchesThePlaneGeometryOfTheTurningPinion) {
  GearPairSpec internal_asym = testing::InternalSpec();
  internal_asym.drive_pressure_angle_rad = DegToRad(25);
  for (const GearPairSpec& s :
       {testing::Seed004Spec(), testing::Seed000Spec(35, 20), testing::Seed000Spec(20, 35),
        Shifted(testing::Seed000Spec(30, 20), 0.3, -0.2), testing::InternalSpec(), internal_asym}) {
    const GearPair pair(s);
    const PlaneMesh g(pair);
    // A and A_c of the construction are the gear core's.
    EXPECT_NEAR(g.a_m[0], pair.line(Flank::kDrive).a_m, 1e-12);
    EXPECT_NEAR(g.a_m[1], pair.line(Flank::kCoast).a_m, 1e-12);
    const double delta = CoastPhaseOffset(pair);
    int found = 0;
    double sd_prev = 0, sc_prev = 0;
    for (int i = 0; i < 24; ++i) {
      const double psi = 2 * kPi / g.z1 * i / 24;
      const double sd = g.Crossing(0, psi), sc = g.Crossing(1, psi);
      if (std::isnan(sd) || std::isnan(sc)) continue;
      ++found;
      EXPECT_NEAR(Wrap(sc / g.pitch[1] + sd / g.pitch[0] - delta), 0.0, 1e-9)
          << "psi " << psi << " s_d " << sd << " s_c " << sc;
      if (i > 0) {  // turning forward (clockwise) the drive contacts advance, the coast ones
                    // run back, each by its base radius times the turn
        const double step = 2 * kPi / g.z1 / 24;
        EXPECT_NEAR(Wrap((sd - sd_prev) / g.pitch[0] - g.rb[0] * step / g.pitch[0]), 0.0, 1e-9);
        EXPECT_NEAR(Wrap((sc - sc_prev) / g.pitch[1] + g.rb[1] * step / g.pitch[1]), 0.0, 1e-9);
      }
      sd_prev = sd;
      sc_prev = sc;
    }
    EXPECT_GE(found, 20);
  }
}

}  // namespace
}  // namespace tehl

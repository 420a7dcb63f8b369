#include "tehl/gear/tooth_profile.hpp"

#include <algorithm>
#include <cmath>

#include "tehl/gear/involute.hpp"

namespace tehl {
namespace {

// Polar angle from +y (positive towards +x) of a flank point at radius r [rad].
double FlankAngle(double share_m, double pitch_radius_m, const FlankGeometry& f, double r) {
  return share_m / pitch_radius_m + Involute(f.pressure_angle_rad) -
         Involute(ProfileAngleAtRadius(f.base_radius_m, r));
}

ProfilePoint AtPolar(double r, double angle_from_y, double side) {
  return {side * r * std::sin(angle_from_y), r * std::cos(angle_from_y)};
}

struct Fillet {
  std::vector<ProfilePoint> points;  // root -> form circle, on the +x side
  double root_angle = 0;             // polar angle of its lowest point [rad]
};

// The trochoid generated on the +x side by the rack tip rounding next to a flank of
// transverse angle alpha_t (rack frame: rolling line y = r, reference line y = r + x m_n,
// rack space centred on x = 0).
Fillet TrochoidFillet(
    const GearPairSpec& s, const GearGeometry& g, const FlankGeometry& f, double m_t, int n) {
  const double r = g.pitch_radius_m;
  const double mn = s.module_m;
  const double rho = s.root_fillet_coefficient * mn;
  const double at = f.pressure_angle_rad;
  const double yc = r + (g.profile_shift - s.dedendum_coefficient + s.root_fillet_coefficient) * mn;
  const double xc =
      0.25 * kPi * m_t + (r + g.profile_shift * mn - yc) * std::tan(at) + rho / std::cos(at);
  const double k = (r - yc) / std::sin(at);
  const double theta_form =
      -(xc + k * std::cos(at)) / r;   // normal through I along the flank normal
  const double theta_root = -xc / r;  // normal vertical: the root circle
  Fillet out;
  for (int i = 0; i < n; ++i) {
    const double th = theta_root + (theta_form - theta_root) * i / (n - 1);
    const double ix = -r * th, iy = r;  // pitch point in the rack frame
    const double vx = xc - ix, vy = yc - iy, len = std::hypot(vx, vy);
    const double qx = xc + (len > 0 ? rho * vx / len : 0.0);
    const double qy = yc + (len > 0 ? rho * vy / len : -rho);
    const double X = qx + r * th, Y = qy;
    out.points.push_back(
        {std::cos(th) * X - std::sin(th) * Y, std::sin(th) * X + std::cos(th) * Y});
  }
  const ProfilePoint& p0 = out.points.front();
  out.root_angle = std::atan2(p0.x_m, p0.y_m);
  return out;
}

void AddGear(const GearPair& pair,
             int index,
             const ToothProfileOptions& o,
             std::vector<ProfileCurve>* out) {
  const GearPairSpec& s = pair.spec();
  const GearGeometry& g = index == 0 ? pair.pinion() : pair.wheel();
  const std::string name = index == 0 ? "pinion" : "wheel";
  const double m_t = pair.transverse_module_m();
  const double r = g.pitch_radius_m;
  const double pitch_angle = 2.0 * kPi / g.teeth;
  double root_angle[2] = {0, 0};
  double tip_angle[2] = {0, 0};
  for (int side = 0; side < 2; ++side) {
    const Flank flank = side == 0 ? Flank::kDrive : Flank::kCoast;
    const FlankGeometry& f = g.flank(flank);
    const double sign = side == 0 ? 1.0 : -1.0;
    const double share =
        m_t * (0.25 * kPi + g.profile_shift * std::tan(f.normal_pressure_angle_rad));
    // The flank's share of the pitch-circle thickness (a ring: of the space width).
    ProfileCurve c{name, ToString(flank), {}};
    if (!g.internal) {
      Fillet fillet = TrochoidFillet(s, g, f, m_t, std::max(2, o.fillet_points));
      for (auto p : fillet.points) c.points.push_back({sign * p.x_m, p.y_m});
      root_angle[side] = fillet.root_angle;
      const double r0 = std::max(f.form_radius_m, f.base_radius_m);
      const int n = std::max(2, o.involute_points);
      for (int i = 0; i < n; ++i) {
        const double ri = r0 + (g.tip_radius_m - r0) * i / (n - 1);
        c.points.push_back(AtPolar(ri, FlankAngle(share, r, f, ri), sign));
      }
      tip_angle[side] = FlankAngle(share, r, f, g.tip_radius_m);
    } else {
      // The ring's space has the external-tooth form; its flanks run from the tip (inner)
      // circle out to the root circle.
      const double r0 = std::max(g.tip_radius_m, f.base_radius_m);
      const int n = std::max(2, o.involute_points);
      for (int i = 0; i < n; ++i) {
        const double ri = r0 + (g.root_radius_m - r0) * i / (n - 1);
        c.points.push_back(AtPolar(ri, FlankAngle(share, r, f, ri), sign));
      }
      tip_angle[side] = FlankAngle(share, r, f, r0);
      root_angle[side] = FlankAngle(share, r, f, g.root_radius_m);
    }
    out->push_back(std::move(c));
  }
  const int n = std::max(2, o.arc_points);
  auto arc = [&](const std::string& label, double radius, double from, double to) {
    ProfileCurve c{name, label, {}};
    for (int i = 0; i < n; ++i) {
      const double a = from + (to - from) * i / (n - 1);
      c.points.push_back({radius * std::sin(a), radius * std::cos(a)});
    }
    out->push_back(std::move(c));
  };
  if (!g.internal) {
    if (tip_angle[0] + tip_angle[1] > 0)  // a top land exists
      arc("tip", g.tip_radius_m, -tip_angle[1], tip_angle[0]);
    // Root arc from this tooth's drive fillet to the next tooth's coast fillet (skipped when
    // the two fillets cross).
    const double next = pitch_angle - root_angle[1];
    if (next > root_angle[0]) arc("root", g.root_radius_m, root_angle[0], next);
  } else {
    // Ring: the space is centred on +y; the tip arc joins this space's drive side to the
    // next space's coast side, the root arc closes the space.
    arc("root", g.root_radius_m, -root_angle[1], root_angle[0]);
    const double next = pitch_angle - tip_angle[1];
    if (next > tip_angle[0]) arc("tip", std::max(g.tip_radius_m, 0.0), tip_angle[0], next);
  }
}

}  // namespace

std::vector<ProfileCurve> ToothProfile(const GearPair& pair, const ToothProfileOptions& options) {
  std::vector<ProfileCurve> out;
  AddGear(pair, 0, options, &out);
  AddGear(pair, 1, options, &out);
  return out;
}

}  // namespace tehl

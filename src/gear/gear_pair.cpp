#include "tehl/gear/gear_pair.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <utility>

#include "tehl/error.hpp"
#include "tehl/gear/contact_ratio.hpp"
#include "tehl/gear/involute.hpp"
#include "tehl/gear/undercut.hpp"

namespace tehl {
namespace {

constexpr double kHalfPi = 0.5 * kPi;

void RequireValidSpec(const GearPairSpec& s) {
  ProblemList problems;
  auto rule = [&](bool ok, const std::string& key, double value, const std::string& what,
                  const std::string& allowed = "") {
    if (ok) return;
    std::ostringstream v;
    v << value;
    problems.Add({"", 0, key, v.str(), what, allowed});
  };
  const auto finite_positive = [](double v) { return v > 0 && std::isfinite(v); };
  rule(s.pinion.teeth >= 3, "gear.pinion.teeth", s.pinion.teeth, "must be >= 3");
  rule(s.wheel.teeth >= 3, "gear.wheel.teeth", s.wheel.teeth, "must be >= 3");
  rule(finite_positive(s.module_m), "gear.module_m", s.module_m, "must be finite and > 0 [m]");
  rule(finite_positive(s.face_width_m), "gear.face_width_m", s.face_width_m,
       "must be finite and > 0 [m]");
  // Each gear: a finite shift, a tip radius given (> 0) or not (0), and a material.
  for (const auto& [section, m] :
       {std::pair<std::string, const GearMemberSpec*>{"gear.pinion", &s.pinion},
        {"gear.wheel", &s.wheel}}) {
    rule(std::isfinite(m->profile_shift), section + ".profile_shift", m->profile_shift,
         "must be finite", "a shift coefficient, typically -1.5 .. 1.5");
    rule(m->tip_radius_m == 0 || finite_positive(m->tip_radius_m), section + ".tip_radius_m",
         m->tip_radius_m, "must be finite and > 0 [m], or 0 (from module, addendum and shift)");
    const GearMaterial& mat = m->material;
    rule(finite_positive(mat.youngs_modulus_pa), section + ".youngs_modulus_pa",
         mat.youngs_modulus_pa, "must be finite and > 0 [Pa]");
    rule(mat.poisson_ratio >= 0 && mat.poisson_ratio < 0.5, section + ".poisson_ratio",
         mat.poisson_ratio, "must be in [0, 0.5)");
    rule(finite_positive(mat.density_kg_m3), section + ".density_kg_m3", mat.density_kg_m3,
         "must be finite and > 0 [kg/m^3]");
    rule(finite_positive(mat.conductivity_w_mk), section + ".conductivity_w_mk",
         mat.conductivity_w_mk, "must be finite and > 0 [W/(m K)]");
    rule(finite_positive(mat.heat_capacity_j_kgk), section + ".heat_capacity_j_kgk",
         mat.heat_capacity_j_kgk, "must be finite and > 0 [J/(kg K)]");
  }
  rule(s.drive_pressure_angle_rad > 0 && s.drive_pressure_angle_rad < DegToRad(80),
       "gear.pressure_angle_deg", RadToDeg(s.drive_pressure_angle_rad), "must be in (0, 80) [deg]");
  rule(s.coast_pressure_angle_rad > 0 && s.coast_pressure_angle_rad < DegToRad(80),
       "gear.coast_pressure_angle_deg", RadToDeg(s.coast_pressure_angle_rad),
       "must be in (0, 80) [deg]");
  rule(s.helix_angle_rad >= 0 && s.helix_angle_rad < DegToRad(45), "gear.helix_angle_deg",
       RadToDeg(s.helix_angle_rad), "must be in [0, 45) [deg]");
  rule(finite_positive(s.addendum_coefficient), "gear.addendum_coefficient", s.addendum_coefficient,
       "must be finite and > 0");
  rule(finite_positive(s.dedendum_coefficient), "gear.dedendum_coefficient", s.dedendum_coefficient,
       "must be finite and > 0");
  rule(s.root_fillet_coefficient >= 0 && std::isfinite(s.root_fillet_coefficient),
       "gear.root_fillet_coefficient", s.root_fillet_coefficient, "must be finite and >= 0");
  rule(s.center_distance_m == 0 || finite_positive(s.center_distance_m), "gear.center_distance_m",
       s.center_distance_m, "must be finite and > 0 [m], or absent (0)");
  rule(!s.internal || s.wheel.teeth > s.pinion.teeth, "gear.wheel.teeth", s.wheel.teeth,
       "an internal wheel (ring) needs more teeth than the pinion",
       "more than the pinion's " + std::to_string(s.pinion.teeth) +
           " teeth (10 or more beyond it: "
           "docs/gear.md section 3)");
  problems.ThrowIfAny();
}

// Sum of the involute functions of both flanks' working angles when the drive flank's is
// w and the coast flank's follows from the base-radius ratio: cos(w_c) = k cos(w).
double FlankInvoluteSum(double w, double k) {
  return Involute(w) + Involute(std::acos(std::min(1.0, k * std::cos(w))));
}

// Solves FlankInvoluteSum(w, k) = target for w (Newton, safeguarded by bisection).
// Returns the lower end of the admissible range when target is below it.
double SolveWorkingAngle(double target, double k) {
  double lo = k > 1.0 ? std::acos(1.0 / k) : 0.0;
  double hi = kHalfPi * (1.0 - 1e-9);
  if (target <= FlankInvoluteSum(lo, k)) return lo;
  double w = std::clamp(InverseInvolute(0.5 * target), lo, hi);
  for (int i = 0; i < 200; ++i) {
    const double f = FlankInvoluteSum(w, k) - target;
    if (f > 0)
      hi = w;
    else
      lo = w;
    if (std::abs(f) <= 1e-15 * target) break;
    const double wc = std::acos(std::min(1.0, k * std::cos(w)));
    const double t = std::tan(w);
    // d inv(w)/dw = tan^2 w; d w_c/dw = k sin w / sin w_c, tan^2(w_c)/sin(w_c) = sin w_c/cos^2 w_c.
    const double dfdw = t * t + std::sin(wc) / (std::cos(wc) * std::cos(wc)) * k * std::sin(w);
    double next = w - f / dfdw;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == w) break;
    w = next;
  }
  return w;
}

FlankGeometry MakeFlank(
    const GearPairSpec& s, double pitch_radius, int z, double x, bool ring, double alpha_n) {
  FlankGeometry f;
  const double beta = s.helix_angle_rad;
  f.normal_pressure_angle_rad = alpha_n;
  f.pressure_angle_rad = HelicalTransverse(s.module_m, alpha_n, beta).pressure_angle_rad;
  f.base_radius_m = pitch_radius * std::cos(f.pressure_angle_rad);
  f.base_pitch_m = 2.0 * kPi * f.base_radius_m / z;
  if (ring) {
    f.form_radius_m = 0;  // set by the caller to the root radius
    f.min_shift_no_undercut = -std::numeric_limits<double>::infinity();
    return f;
  }
  const double sin_t = std::sin(f.pressure_angle_rad);
  // The generating rack's straight flank ends h_F0 m_n below the reference line, h_F0 = h_fP -
  // rho_fP (1 - sin alpha_n) (ISO 21771 d_Ff). Undercut starts when that end passes the
  // interference point T (the involute then reaches the base circle): (h_F0 - x) m_n >=
  // r sin^2(alpha_t). The textbook rule with h_aP* in place of h_F0 is the same for racks
  // whose straight flank ends at the working depth (ISO 53: 0.99997) and misses the undercut
  // of sharper tools (rho_fP = 0: h_F0 = h_fP).
  const double h0 = s.dedendum_coefficient - s.root_fillet_coefficient * (1.0 - std::sin(alpha_n));
  f.min_shift_no_undercut = h0 - z * sin_t * sin_t / (2.0 * std::cos(beta));
  f.undercut = x < f.min_shift_no_undercut;
  // Form circle from the same rack: where its straight flank ends, or on an undercut flank
  // where the rack's tip stops cutting the involute (undercut.hpp).
  const double q = pitch_radius * sin_t - (h0 - x) * s.module_m / sin_t;
  if (q > 0) {
    f.form_radius_m = std::hypot(f.base_radius_m, q);
  } else {
    RackCut rack;
    rack.pitch_radius_m = pitch_radius;
    rack.pressure_angle_rad = f.pressure_angle_rad;
    rack.normal_pressure_angle_rad = alpha_n;
    rack.module_m = s.module_m;
    rack.profile_shift = x;
    rack.dedendum_coefficient = s.dedendum_coefficient;
    rack.root_fillet_coefficient = s.root_fillet_coefficient;
    f.form_radius_m = std::hypot(f.base_radius_m, UndercutRollLength(rack));
  }
  return f;
}

// Pointed-tip radius of an external tooth: s(r) = 0 by bisection (Kapelevich's intersection
// of the two involutes, seed 000 eqs. 3.19-3.25).
double PointedRadius(const GearGeometry& g) {
  double lo = std::max(g.drive.base_radius_m, g.coast.base_radius_m);
  if (g.ThicknessAtRadius(lo) <= 0) return lo;
  double hi = lo * 1.05;
  while (g.ThicknessAtRadius(hi) > 0 && hi < lo * 1e3) hi *= 1.5;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g.ThicknessAtRadius(mid) > 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

std::string ToString(Flank flank) { return flank == Flank::kDrive ? "drive" : "coast"; }

double GearGeometry::ThicknessAtRadius(double r) const {
  const double inv_ref = Involute(drive.pressure_angle_rad) + Involute(coast.pressure_angle_rad);
  const double inv_r = Involute(ProfileAngleAtRadius(drive.base_radius_m, r)) +
                       Involute(ProfileAngleAtRadius(coast.base_radius_m, r));
  if (!internal) return r * (reference_thickness_m / pitch_radius_m + inv_ref - inv_r);
  // A ring: its space has the form of an external tooth; the tooth is the rest of the pitch.
  const double space_ref = 2.0 * kPi * pitch_radius_m / teeth - reference_thickness_m;
  return 2.0 * kPi * r / teeth - r * (space_ref / pitch_radius_m + inv_ref - inv_r);
}

double TipRadiusForTopLand(const GearGeometry& g, double land) {
  double lo = std::max(g.drive.base_radius_m, g.coast.base_radius_m);
  double hi = g.internal ? lo : g.pointed_tip_radius_m;
  if (g.ThicknessAtRadius(lo) <= land) return lo;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g.ThicknessAtRadius(mid) > land ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

GearPair::GearPair(const GearPairSpec& spec) : spec_(spec) {
  RequireValidSpec(spec_);
  const auto& s = spec_;
  const bool ring = s.internal;
  transverse_module_m_ =
      HelicalTransverse(s.module_m, s.drive_pressure_angle_rad, s.helix_angle_rad).module_m;
  const double tan_sum =
      std::tan(s.drive_pressure_angle_rad) + std::tan(s.coast_pressure_angle_rad);
  const GearMemberSpec* members[2] = {&s.pinion, &s.wheel};
  for (int i = 0; i < 2; ++i) {
    const GearMemberSpec& m = *members[i];
    GearGeometry& g = gear_[i];
    const bool is_ring = ring && i == 1;
    g.teeth = m.teeth;
    g.internal = is_ring;
    g.profile_shift = m.profile_shift;
    g.pitch_radius_m = 0.5 * m.teeth * transverse_module_m_;
    const double mn = s.module_m;
    if (is_ring) {
      g.tip_radius_m = g.pitch_radius_m - mn * (s.addendum_coefficient - m.profile_shift);
      g.root_radius_m = g.pitch_radius_m + mn * (s.dedendum_coefficient + m.profile_shift);
    } else {
      g.tip_radius_m = g.pitch_radius_m + mn * (s.addendum_coefficient + m.profile_shift);
      g.root_radius_m = g.pitch_radius_m - mn * (s.dedendum_coefficient - m.profile_shift);
    }
    if (m.tip_radius_m > 0) g.tip_radius_m = m.tip_radius_m;
    // Rack-generated thickness (a ring: its space width) at the pitch circle.
    const double generated = transverse_module_m_ * (0.5 * kPi + m.profile_shift * tan_sum);
    g.reference_thickness_m = is_ring ? kPi * transverse_module_m_ - generated : generated;
    g.drive = MakeFlank(s, g.pitch_radius_m, m.teeth, m.profile_shift, is_ring,
                        s.drive_pressure_angle_rad);
    g.coast = MakeFlank(s, g.pitch_radius_m, m.teeth, m.profile_shift, is_ring,
                        s.coast_pressure_angle_rad);
    if (is_ring) g.drive.form_radius_m = g.coast.form_radius_m = g.root_radius_m;
    g.tip_thickness_m = g.ThicknessAtRadius(g.tip_radius_m);
    g.pointed_tip_radius_m = is_ring ? 0.0 : PointedRadius(g);
  }
  const GearGeometry& p = gear_[0];
  const GearGeometry& w = gear_[1];

  // Centre distance: zero backlash from the shifts, or as given.
  reference_center_distance_m_ =
      ring ? w.pitch_radius_m - p.pitch_radius_m : w.pitch_radius_m + p.pitch_radius_m;
  const double z_sum = ring ? w.teeth - p.teeth : w.teeth + p.teeth;
  const double x_sum = ring ? w.profile_shift - p.profile_shift : w.profile_shift + p.profile_shift;
  const double inv_ref =
      Involute(p.drive.pressure_angle_rad) + Involute(p.coast.pressure_angle_rad);
  const double k = p.BaseRadiusRatio();
  const double target = inv_ref + 2.0 * x_sum * tan_sum / z_sum;
  const double w_free = SolveWorkingAngle(target, k);
  const double cos_td = std::cos(p.drive.pressure_angle_rad);
  zero_backlash_distance_m_ = reference_center_distance_m_ * cos_td / std::cos(w_free);
  center_distance_m_ = s.center_distance_m > 0 ? s.center_distance_m : zero_backlash_distance_m_;
  const double a = center_distance_m_;

  // Working pressure angle of each flank at a: cos(alpha_wt) = a0 cos(alpha_t) / a.
  double alpha_w[2];
  for (int f = 0; f < 2; ++f) {
    const double c =
        reference_center_distance_m_ * std::cos(p.flank(Flank(f)).pressure_angle_rad) / a;
    alpha_w[f] = std::acos(std::min(1.0, c));
  }
  // Backlash on the pinion's working pitch circle r_w1 = a z1 / (z2 +/- z1).
  const double inv_w = Involute(alpha_w[0]) + Involute(alpha_w[1]);
  const double rw1 = a * p.teeth / z_sum;
  const double psi1 = p.reference_thickness_m / p.pitch_radius_m + inv_ref - inv_w;
  // Angular tooth thickness of the wheel at its working circle (a ring: its space width).
  const double w_generated =
      ring ? kPi * transverse_module_m_ - w.reference_thickness_m : w.reference_thickness_m;
  const double psi2 = w_generated / w.pitch_radius_m + inv_ref - inv_w;
  const double rw2 = a * w.teeth / z_sum;
  backlash_m_ =
      ring ? rw2 * psi2 - rw1 * psi1 : 2.0 * kPi * rw1 / p.teeth - rw1 * psi1 - rw2 * psi2;

  if (ring) {
    clearance_m_[0] = w.root_radius_m - (a + p.tip_radius_m);
    clearance_m_[1] = (w.tip_radius_m - a) - p.root_radius_m;
  } else {
    clearance_m_[0] = a - p.tip_radius_m - w.root_radius_m;
    clearance_m_[1] = a - w.tip_radius_m - p.root_radius_m;
  }

  for (int f = 0; f < 2; ++f) {
    const Flank flank = Flank(f);
    LineOfAction& l = line_[f];
    l.flank = flank;
    l.working_pressure_angle_rad = alpha_w[f];
    l.pinion_base_radius_m = p.flank(flank).base_radius_m;
    l.wheel_base_radius_m = w.flank(flank).base_radius_m;
    l.base_pitch_m = p.flank(flank).base_pitch_m;
    l.tangent_length_m = a * std::sin(alpha_w[f]);
    const double roll2 = RollDistance(l.wheel_base_radius_m, w.tip_radius_m);
    l.a_m = ring ? roll2 - l.tangent_length_m : l.tangent_length_m - roll2;
    l.e_m = RollDistance(l.pinion_base_radius_m, p.tip_radius_m);
    l.c_m = l.pinion_base_radius_m * std::tan(alpha_w[f]);
    l.b_m = l.e_m - l.base_pitch_m;
    l.d_m = l.a_m + l.base_pitch_m;
    l.length_m = l.e_m - l.a_m;
    l.contact_ratio =
        ring
            ? InternalTransverseContactRatio(p.tip_radius_m, l.pinion_base_radius_m, w.tip_radius_m,
                                             l.wheel_base_radius_m, a, alpha_w[f], l.base_pitch_m)
            : ExternalTransverseContactRatio(p.tip_radius_m, l.pinion_base_radius_m, w.tip_radius_m,
                                             l.wheel_base_radius_m, a, alpha_w[f], l.base_pitch_m);
  }
}

double GearPair::gear_ratio() const { return static_cast<double>(gear_[1].teeth) / gear_[0].teeth; }

double GearPair::center_distance_modification() const {
  return (center_distance_m_ - reference_center_distance_m_) / spec_.module_m;
}

double GearPair::face_contact_ratio() const {
  return FaceContactRatio(spec_.face_width_m, spec_.helix_angle_rad, spec_.module_m);
}

double GearPair::total_contact_ratio() const {
  return line_[0].contact_ratio + face_contact_ratio();
}

}  // namespace tehl

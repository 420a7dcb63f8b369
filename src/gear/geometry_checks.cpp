#include "tehl/gear/geometry_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "tehl/error.hpp"
#include "tehl/gear/contact_ratio.hpp"
#include "tehl/gear/involute.hpp"

namespace tehl {
namespace {

// The smallest radial tip clearance that passes without a warning, in normal modules (ISO
// 53's basic rack gives c = 0.25 m_n; profile-shifted pairs brought closer lose part of it
// unless their tips are shortened) [-].
constexpr double kMinTipClearance = 0.15;

// Tooth difference of an internal pair below which it is warned of trochoid interference:
// with 20 deg full-depth teeth, differences below about 10 commonly foul unless the teeth are
// shortened or shifted (the exact limit needs the trochoid, not computed here) [-].
constexpr int kMinRingToothDifference = 10;

// Lengths in messages: millimetres with 4 significant decimals.
std::string Mm(double metres) {
  std::ostringstream s;
  s.precision(4);
  s << std::fixed << metres * 1e3 << " mm";
  return s.str();
}

std::string Num(double x, int decimals = 4) {
  std::ostringstream s;
  s.precision(decimals);
  s << std::fixed << x;
  return s.str();
}

class Checker {
 public:
  explicit Checker(const GearPair& pair) : pair_(pair), s_(pair.spec()) {}

  std::vector<GeometryProblem> Run() {
    const bool meshes = CenterDistance();
    BasicRack();
    for (int i = 0; i < 2; ++i) Member(i);
    // Below the base radii's sum (difference) there is no line of action: what follows would
    // be computed from an impossible geometry.
    if (!meshes) return std::move(out_);
    for (Flank f : {Flank::kDrive, Flank::kCoast}) {
      if (f == Flank::kCoast && Symmetric()) break;
      Interference(f);
    }
    Clearances();
    ContactRatios();
    ToothDifference();
    return std::move(out_);
  }

 private:
  bool Symmetric() const { return s_.drive_pressure_angle_rad == s_.coast_pressure_angle_rad; }
  static const char* Section(int i) { return i == 0 ? "gear.pinion" : "gear.wheel"; }
  static const char* Name(int i) { return i == 0 ? "pinion" : "wheel"; }
  const GearGeometry& Gear(int i) const { return i == 0 ? pair_.pinion() : pair_.wheel(); }
  std::string FlankLabel(Flank f) const {
    return Symmetric() ? "" : " (" + ToString(f) + " flank)";
  }
  // The key a user changes to move a tip: the tip radius if given, else the shift.
  std::string TipKey(int i) const {
    const GearMemberSpec& m = i == 0 ? s_.pinion : s_.wheel;
    return m.tip_radius_m > 0 ? "tip_radius_m" : "profile_shift";
  }
  // Where a flank's involute begins, for messages.
  static std::string FormCircle(const FlankGeometry& fl, double r_form) {
    return fl.undercut ? "the end of its undercut r_F = " + Mm(r_form) +
                             " (the generating rack's tip has cut the involute away below it)"
                       : "its involute form circle r_F = " + Mm(r_form) + " (in the root fillet)";
  }
  std::string Who(int i) const { return i == 0 ? "pinion" : s_.internal ? "ring" : "wheel"; }
  // What gear i's tip radius must be, said with the key the problem names: a shift moves the
  // tip with it (r_a = r + (h_aP + x) m_n outwards, a ring's inner tip too: a positive ring
  // shift shortens its teeth).
  std::string TipTo(int i, bool at_least, double limit_m) const {
    std::string t =
        "a " + Who(i) + " tip radius " + (at_least ? "of at least " : "of at most ") + Mm(limit_m);
    if (TipKey(i) == "profile_shift")
      t += std::string(" (tip_radius_m, or a ") + (at_least ? "larger " : "smaller ") + Who(i) +
           " profile_shift)";
    return t;
  }

  void Error(std::string section, std::string key, std::string rule, std::string allowed) {
    out_.push_back(
        {std::move(section), std::move(key), std::move(rule), std::move(allowed), false});
  }
  void Warning(std::string section, std::string key, std::string rule, std::string allowed) {
    out_.push_back({std::move(section), std::move(key), std::move(rule), std::move(allowed), true});
  }

  // False when the involutes cannot mesh at all.
  bool CenterDistance() {
    const double a = pair_.center_distance_m();
    const double a_free = pair_.zero_backlash_center_distance_m();
    for (Flank f : {Flank::kDrive, Flank::kCoast}) {
      const double c = pair_.reference_center_distance_m() *
                       std::cos(pair_.pinion().flank(f).pressure_angle_rad) / a;
      if (c > 1.0) {
        Error("gear", "center_distance_m",
              "a = " + Mm(a) + " is below the " + (s_.internal ? "difference" : "sum") +
                  " of the base radii" + FlankLabel(f) + ": the involutes cannot mesh",
              "center_distance_m >= " + Num(a_free, 6) +
                  " (the zero-backlash distance of the given shifts)");
        return false;
      }
    }
    const double tolerance = 1e-4 * s_.module_m;
    if (pair_.backlash_m() < -tolerance) {
      Error("gear", "center_distance_m",
            "the teeth overlap at a = " + Mm(a) + ": backlash " + Num(pair_.backlash_m() * 1e6, 2) +
                " um with profile shifts x1 = " + Num(s_.pinion.profile_shift) +
                ", x2 = " + Num(s_.wheel.profile_shift),
            // A ring's backlash e_w2 - s_w1 grows as the pinion moves toward its centre,
            // and a positive ring shift widens the ring's spaces.
            s_.internal ? "center_distance_m <= " + Num(a_free, 6) +
                              " [m] (zero backlash), a smaller pinion profile_shift or a "
                              "larger ring profile_shift"
                        : "center_distance_m >= " + Num(a_free, 6) +
                              " [m] (zero backlash), or smaller profile shifts");
    }
    return true;
  }

  void BasicRack() {
    const double tan_sum =
        std::tan(s_.drive_pressure_angle_rad) + std::tan(s_.coast_pressure_angle_rad);
    // Rack tooth width at its tip (depth h_fP below the reference line, tooth = space there):
    const double tip_width = 0.5 * kPi - s_.dedendum_coefficient * tan_sum;  // [m_n]
    if (tip_width <= 0) {
      Error("gear", "dedendum_coefficient",
            "the basic rack tooth is pointed at depth h_fP: its tip width is " + Num(tip_width) +
                " m_n",
            "dedendum_coefficient < " + Num(0.5 * kPi / tan_sum) + " for these pressure angles");
      return;
    }
    auto corner = [](double a) { return (1.0 - std::sin(a)) / std::cos(a); };
    const double rho_max =
        tip_width / (corner(s_.drive_pressure_angle_rad) + corner(s_.coast_pressure_angle_rad));
    if (s_.root_fillet_coefficient > rho_max * (1.0 + 1e-12)) {
      Error("gear", "root_fillet_coefficient",
            "the rack tip radius rho_fP = " + Num(s_.root_fillet_coefficient) +
                " m_n does not fit on the rack tooth tip (width " + Num(tip_width) + " m_n)",
            "root_fillet_coefficient <= " + Num(rho_max) + " for these pressure angles");
    }
  }

  void Member(int i) {
    const GearGeometry& g = Gear(i);
    const char* sec = Section(i);
    for (Flank f : {Flank::kDrive, Flank::kCoast}) {
      if (f == Flank::kCoast && Symmetric()) break;
      const FlankGeometry& fl = g.flank(f);
      if (g.tip_radius_m <= fl.base_radius_m) {
        Error(sec, TipKey(i),
              std::string("the ") + Name(i) + " tip circle r_a = " + Mm(g.tip_radius_m) +
                  " lies inside its base circle r_b = " + Mm(fl.base_radius_m) + FlankLabel(f),
              "a tip radius above the base circle (more teeth or a positive shift)");
      }
      if (!g.internal && fl.undercut) {
        const std::string rule = std::string("the ") + Name(i) + " is undercut" + FlankLabel(f) +
                                 ": x = " + Num(g.profile_shift) +
                                 " < x_min = " + Num(fl.min_shift_no_undercut) +
                                 " for z = " + std::to_string(g.teeth);
        if (s_.allow_undercut) {
          Warning(sec, "profile_shift",
                  rule + " (accepted: allow_undercut = true; its involute begins at r_F = " +
                      Mm(fl.form_radius_m) + ", where the rack's tip stops cutting it)",
                  "profile_shift >= " + Num(fl.min_shift_no_undercut));
        } else {
          Error(sec, "profile_shift", rule,
                "profile_shift >= " + Num(fl.min_shift_no_undercut) +
                    ", more teeth, or [gear] allow_undercut = true");
        }
      }
    }
    const double land = g.tip_thickness_m;
    if (land <= 0) {
      Error(sec, TipKey(i),
            std::string("the ") + Name(i) + " tooth is pointed: top land " + Mm(land) +
                " at r_a = " + Mm(g.tip_radius_m) +
                (g.internal ? std::string()
                            : "; the flanks meet at r = " + Mm(g.pointed_tip_radius_m)),
            g.internal ? "a larger ring tip radius (positive profile_shift)"
                       : "tip_radius_m below " + Mm(g.pointed_tip_radius_m) + " (" +
                             Mm(TipRadiusForTopLand(g, 0.2 * s_.module_m)) +
                             " leaves a top land of 0.2 m_n), or a smaller profile_shift");
    } else if (land < 0.2 * s_.module_m) {
      Warning(sec, TipKey(i),
              std::string("thin top land on the ") + Name(i) + ": " + Mm(land) +
                  " < 0.2 m_n = " + Mm(0.2 * s_.module_m),
              g.internal
                  ? std::string("a larger ring tip radius (positive profile_shift)")
                  : "a tip radius of at most " + Mm(TipRadiusForTopLand(g, 0.2 * s_.module_m)) +
                        " or a smaller profile shift");
    }
  }

  void Interference(Flank f) {
    const LineOfAction& l = pair_.line(f);
    const GearGeometry& p = pair_.pinion();
    const GearGeometry& w = pair_.wheel();
    if (p.tip_radius_m <= p.flank(f).base_radius_m || w.tip_radius_m <= w.flank(f).base_radius_m)
      return;  // already reported
    // Pinion: the wheel's tip circle must cross the line of action at or beyond T1
    // (seed 000 eq. 3.36: tan(phi_f1) = (1 + u) tan(alpha_w) - u tan(alpha_a2) >= 0).
    if (l.a_m < 0) {
      Error("gear.wheel", TipKey(1),
            "involute interference" + FlankLabel(f) + ": the wheel tip reaches " + Mm(-l.a_m) +
                " beyond the tangent point T1 of the pinion's base circle",
            // The limit circle through T1: sqrt(r_b2^2 + T1T2^2) (seed 000 eq. 2.17); a ring's
            // tip (its inner circle) must lie outside it, an external wheel's inside.
            TipTo(1, s_.internal, std::hypot(l.wheel_base_radius_m, l.tangent_length_m)) +
                (s_.internal ? "" : ", a positive pinion profile_shift, or more pinion teeth"));
    } else {
      const double r_sap = std::hypot(l.pinion_base_radius_m, l.a_m);
      const double r_form = p.flank(f).form_radius_m;
      if (r_sap < r_form - 1e-9) {
        // The wheel tip circle that crosses the line of action at the pinion's form circle,
        // at the roll length rho_F = sqrt(r_F^2 - r_b1^2) from T1: A = T1T2 - sqrt(r_a2^2 -
        // r_b2^2) for an external wheel, sqrt(r_a2^2 - r_b2^2) - T1T2 for a ring. A ring's tip
        // must lie outside that circle (a shorter ring tooth), an external wheel's inside.
        const double roll_form = std::sqrt(
            std::max(0.0, r_form * r_form - l.pinion_base_radius_m * l.pinion_base_radius_m));
        const double limit =
            std::hypot(l.wheel_base_radius_m, s_.internal ? l.tangent_length_m + roll_form
                                                          : l.tangent_length_m - roll_form);
        Error("gear.wheel", TipKey(1),
              "involute interference" + FlankLabel(f) + ": the wheel tip meets the pinion at r = " +
                  Mm(r_sap) + ", below " + FormCircle(p.flank(f), r_form),
              TipTo(1, s_.internal, limit) + ", or a larger pinion profile_shift");
      }
    }
    if (s_.internal) return;  // the pinion tip meets the ring beyond T2 on the far side
    // Wheel: the pinion's tip circle must cross the line at or before T2 (eq. 3.37).
    const double roll2 = l.tangent_length_m - l.e_m;
    if (roll2 < 0) {
      Error("gear.pinion", TipKey(0),
            "involute interference" + FlankLabel(f) + ": the pinion tip reaches " + Mm(-roll2) +
                " beyond the tangent point T2 of the wheel's base circle",
            TipTo(0, false, std::hypot(l.pinion_base_radius_m, l.tangent_length_m)) +
                ", a positive wheel profile_shift, or more wheel teeth");
    } else {
      const double r_sap = std::hypot(l.wheel_base_radius_m, roll2);
      const double r_form = w.flank(f).form_radius_m;
      if (r_sap < r_form - 1e-9) {
        Error("gear.pinion", TipKey(0),
              "involute interference" + FlankLabel(f) + ": the pinion tip meets the wheel at r = " +
                  Mm(r_sap) + ", below " + FormCircle(w.flank(f), r_form),
              TipTo(0, false,
                    std::hypot(l.pinion_base_radius_m,
                               l.tangent_length_m -
                                   std::sqrt(std::max(
                                       0.0, r_form * r_form -
                                                l.wheel_base_radius_m * l.wheel_base_radius_m)))) +
                  ", or a larger wheel profile_shift");
      }
    }
  }

  // Internal pairs whose tooth counts differ little foul outside the line of action: the
  // pinion's tip sweeps a trochoid through the ring's tooth space as it leaves (tip or
  // trochoid interference), which the checks on the line of action above do not see. Not
  // computed here; below kMinRingToothDifference teeth it is likely at 20 deg full depth.
  void ToothDifference() {
    if (!s_.internal) return;
    const int d = s_.wheel.teeth - s_.pinion.teeth;
    if (d >= kMinRingToothDifference) return;
    Warning("gear.wheel", "teeth",
            "the ring has only " + std::to_string(d) +
                " teeth more than the pinion: internal pairs this close foul outside the "
                "line of action (tip and trochoid interference as the pinion's tip leaves), "
                "which is not checked here (docs/gear.md section 3)",
            "a tooth difference of " + std::to_string(kMinRingToothDifference) +
                " or more, or a check of the trochoid by a gear design program");
  }

  void Clearances() {
    for (int i = 0; i < 2; ++i) {
      const double c = i == 0 ? pair_.pinion_tip_clearance_m() : pair_.wheel_tip_clearance_m();
      // Round-off of a tip that just touches the root circle is no overlap.
      if (c < -1e-9 * s_.module_m) {
        // A ring's tip is its inner circle: its teeth shorten as it grows; the pinion moves
        // away from both of a ring's circles as the centre distance shrinks.
        const double tip = Gear(i).tip_radius_m;
        const bool ring = i == 1 && s_.internal;
        Error(Section(i), TipKey(i),
              "the " + Who(i) + " tip reaches " + Mm(-c) + " into the " + Who(1 - i) +
                  "'s root circle",
              TipTo(i, ring, ring ? tip - c : tip + c) + " (tip shortening), or a " +
                  (s_.internal ? "smaller" : "larger") + " center_distance_m");
      } else if (c < kMinTipClearance * s_.module_m) {
        // Profile-shifted pairs at a centre distance below a0 + (x1 + x2) m_n keep the tips of
        // r + m (h_aP + x) unless shortened: the clearance shrinks (tip radii as given or
        // as computed; this program does not shorten them).
        Warning(Section(i), TipKey(i),
                std::string("the ") + Name(i) + " tip clears the " + Name(1 - i) +
                    "'s root circle by only " + Mm(c) + " (" + Num(c / s_.module_m, 3) +
                    " m_n; the basic rack gives 0.25 m_n): the tips are not shortened for the "
                    "centre distance, and the contact ratio is that of the full tips",
                "a clearance of at least " + Num(kMinTipClearance, 2) +
                    " m_n: a smaller tip_radius_m (tip shortening)");
      }
    }
  }

  void ContactRatios() {
    // A centre distance opened beyond zero backlash shortens the path of contact: it is the
    // key to blame when the contact ratio is too small.
    const bool opened = s_.center_distance_m > 0 &&
                        pair_.center_distance_m() >
                            pair_.zero_backlash_center_distance_m() + 1e-4 * s_.module_m;
    for (Flank f : {Flank::kDrive, Flank::kCoast}) {
      if (f == Flank::kCoast && Symmetric()) break;
      const double eps = pair_.line(f).contact_ratio;
      const std::string angle_key =
          f == Flank::kDrive ? "pressure_angle_deg" : "coast_pressure_angle_deg";
      const ContactRatioAssessment r = AssessContactRatio(eps);
      const std::string what =
          eps > 0 ? "transverse contact ratio" + FlankLabel(f) + " eps_alpha = " + Num(eps)
                  : "the tip circles" + FlankLabel(f) +
                        " do not overlap on the line of action (no contact): eps_alpha";
      const bool tips_given = s_.pinion.tip_radius_m > 0 || s_.wheel.tip_radius_m > 0;
      const std::string longer =
          tips_given ? std::string(s_.internal ? "a larger pinion and a smaller ring tip_radius_m"
                                               : "larger tip radii (tip_radius_m)")
                     : "longer addenda (addendum_coefficient)";
      std::string raise = "eps_alpha >= 1.2 (seed 003 section 4.1): more teeth, " + longer +
                          " or a smaller pressure angle";
      if (opened)
        raise = "eps_alpha >= 1.2 (seed 003 section 4.1): center_distance_m nearer " +
                Num(pair_.zero_backlash_center_distance_m(), 6) +
                " [m] (zero backlash), more teeth or " + longer;
      // The key a user changed from the standard: an opened centre distance, a tip radius
      // given, a short addendum, else the pressure angle.
      std::string section = "gear";
      std::string key = !r.continuous && opened                 ? "center_distance_m"
                        : s_.addendum_coefficient < 1.0 - 1e-12 ? "addendum_coefficient"
                                                                : angle_key;
      if (!(!r.continuous && opened) && tips_given) {
        section = s_.pinion.tip_radius_m > 0 ? "gear.pinion" : "gear.wheel";
        key = "tip_radius_m";
      }
      if (!r.continuous) {
        if (f == Flank::kDrive)
          Error(section, key, what + " < 1: the mesh is not continuous",
                "eps_alpha >= 1, 1.2 or more recommended (seed 003 section 4.1): " +
                    raise.substr(raise.find(": ") + 2));
        else
          Warning(section, key, what + " < 1: the coast flank cannot carry a reversed drive",
                  raise);
      } else if (r.below_minimum) {
        Warning(section, key, what + " < 1.2, the usual industrial minimum", raise);
      } else if (r.near_integer) {
        Warning(section, key, what + " is close to an integer: mesh impacts synchronise",
                "a contact ratio away from integers (seed 003 section 4.1)");
      }
    }
  }

  const GearPair& pair_;
  const GearPairSpec& s_;
  std::vector<GeometryProblem> out_;
};

}  // namespace

std::string GeometryProblem::ToString() const {
  std::string s = section + "." + key + ": " + rule;
  if (!allowed.empty()) s += " (allowed: " + allowed + ")";
  return s;
}

std::vector<GeometryProblem> CheckGeometry(const GearPair& pair) { return Checker(pair).Run(); }

std::vector<GeometryProblem> RequireValidGeometry(const GearPair& pair) {
  ProblemList errors;
  std::vector<GeometryProblem> warnings;
  for (auto& p : CheckGeometry(pair)) {
    if (p.warning)
      warnings.push_back(std::move(p));
    else
      errors.Add({"", 0, p.section + "." + p.key, "", p.rule, p.allowed});
  }
  errors.ThrowIfAny();
  return warnings;
}

}  // namespace tehl

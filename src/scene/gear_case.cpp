#include "scene/gear_case.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <tuple>

#include "drive/motor_schema.hpp"
#include "scene/dynamic_load.hpp"
#include "tehl/error.hpp"
#include "tehl/gear/operating_point.hpp"
#include "tehl/gear/path_of_contact.hpp"
#include "tehl/gear/tooth_blank.hpp"
#include "tehl/units.hpp"

namespace tehl::internal {
namespace {

// "gear.pinion.teeth" -> ("gear.pinion", "teeth").
std::pair<std::string, std::string> SplitKey(const std::string& full) {
  const auto dot = full.rfind('.');
  if (dot == std::string::npos) return {full, ""};
  return {full.substr(0, dot), full.substr(dot + 1)};
}

void AddProblems(Document& doc, const InputError& e) {
  for (const auto& p : e.problems()) {
    const auto [section, key] = SplitKey(p.key);
    doc.Problem(section, key, p.rule, p.allowed);
  }
}

bool GearKeysInError(const Document& doc) {
  for (const auto& p : doc.problems())
    if (p.key.rfind("gear", 0) == 0 || p.key.rfind("[gear", 0) == 0 ||
        p.key.rfind("operating", 0) == 0 || p.key.rfind("[operating", 0) == 0)
      return true;
  return false;
}

GearMemberSpec ReadMember(const Document& doc, const std::string& section) {
  GearMemberSpec m;
  m.teeth = static_cast<int>(doc.Int(section, "teeth"));
  m.profile_shift = doc.Real(section, "profile_shift");
  if (doc.Given(section, "tip_radius_m")) m.tip_radius_m = doc.Real(section, "tip_radius_m");
  m.material.youngs_modulus_pa = doc.Real(section, "youngs_modulus_pa");
  m.material.poisson_ratio = doc.Real(section, "poisson_ratio");
  m.material.density_kg_m3 = doc.Real(section, "density_kg_m3");
  m.material.conductivity_w_mk = doc.Real(section, "conductivity_w_mk");
  m.material.heat_capacity_j_kgk = doc.Real(section, "heat_capacity_j_kgk");
  return m;
}

GearPairSpec ReadSpec(const Document& doc) {
  GearPairSpec s;
  s.pinion = ReadMember(doc, "gear.pinion");
  s.wheel = ReadMember(doc, "gear.wheel");
  s.module_m = doc.Real("gear", "module_m");
  s.face_width_m = doc.Real("gear", "face_width_m");
  s.drive_pressure_angle_rad = DegToRad(doc.Real("gear", "pressure_angle_deg"));
  s.coast_pressure_angle_rad = doc.Given("gear", "coast_pressure_angle_deg")
                                   ? DegToRad(doc.Real("gear", "coast_pressure_angle_deg"))
                                   : s.drive_pressure_angle_rad;
  s.helix_angle_rad = DegToRad(doc.Real("gear", "helix_angle_deg"));
  if (doc.Given("gear", "center_distance_m"))
    s.center_distance_m = doc.Real("gear", "center_distance_m");
  s.internal = doc.Bool("gear", "internal");
  s.addendum_coefficient = doc.Real("gear", "addendum_coefficient");
  s.dedendum_coefficient = doc.Real("gear", "dedendum_coefficient");
  s.root_fillet_coefficient = doc.Real("gear", "root_fillet_coefficient");
  s.allow_undercut = doc.Bool("gear", "allow_undercut");
  return s;
}

std::string Fmt3(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

TipRelief ReadTipRelief(const Document& doc) {
  TipRelief r;
  auto shape_of = [&](const char* section) {
    const std::string name = doc.Given(section, "tip_relief_shape")
                                 ? doc.String(section, "tip_relief_shape")
                                 : doc.String("gear", "tip_relief_shape");
    return ReliefShapeFromString(name).value_or(ReliefShape::kLinear);
  };
  r.pinion_shape = shape_of("gear.pinion");
  r.wheel_shape = shape_of("gear.wheel");
  r.pinion_amount_m = doc.Real("gear.pinion", "tip_relief_m");
  r.wheel_amount_m = doc.Real("gear.wheel", "tip_relief_m");
  if (doc.Given("gear.pinion", "tip_relief_length_m"))
    r.pinion_length_m = doc.Real("gear.pinion", "tip_relief_length_m");
  if (doc.Given("gear.wheel", "tip_relief_length_m"))
    r.wheel_length_m = doc.Real("gear.wheel", "tip_relief_length_m");
  return r;
}

// The relief's own rules: a length with every amount, within the path, stiffness load
// sharing. Returns false when a rule is broken.
bool CheckTipReliefKeys(Document& doc, const GearCase& c, double g) {
  bool ok = true;
  const TipRelief& r = c.tip_relief;
  char allowed[160];
  for (const auto& [member, amount, length] :
       {std::tuple{"gear.pinion", r.pinion_amount_m, r.pinion_length_m},
        std::tuple{"gear.wheel", r.wheel_amount_m, r.wheel_length_m}}) {
    if (amount > 0 && !doc.Given(member, "tip_relief_length_m")) {
      std::snprintf(allowed, sizeof allowed, "tip_relief_length_m in (0, %.4g] [m] (g_alpha)", g);
      doc.Problem(member, "tip_relief_length_m", "a tip relief needs its length", allowed);
      ok = false;
    } else if (amount > 0 && length > g) {
      std::snprintf(allowed, sizeof allowed, "tip_relief_length_m <= %.4g [m]", g);
      doc.Problem(member, "tip_relief_length_m",
                  "the relief is longer than the path of contact A..E", allowed);
      ok = false;
    }
  }
  if (!r.Active()) return ok;
  if (c.load_sharing == LoadSharing::kLinear) {
    doc.Problem("gear", "load_sharing", "tip relief shares the load by the pair stiffnesses",
                "load_sharing = \"stiffness\" or \"loaded\"");
    ok = false;
  }
  return ok;
}

// Where the tracked pair carries at least kMinFilmShare of F_bt: the films of the mesh cycle
// are solved there. A relief that leaves no such part, or lifts the pair off between its
// ends, is reported at the relief's key.
void FindLoadedPath(Document& doc, GearCase& c) {
  const PathOfContact path(*c.pair, c.operating.pinion_speed_rad_s);
  const double force = NominalToothLoad(*c.pair, c.operating).normal_force_n;
  const double g = path.length_m();
  const CornerContact* corner = c.corner_contact.get();
  c.loaded_path = LoadedPathOf(path, c.pair_stiffness, c.tip_relief, force, kMinFilmShare, corner);
  // The largest amounts that keep the pair loaded to A and to E at this load.
  c.relief_limit_a_m =
      ApproachWithoutPair(path, 0.0, c.pair_stiffness, c.tip_relief, force, corner) -
      (c.tip_relief.GapAt(0.0, g) - c.tip_relief.wheel_amount_m);
  c.relief_limit_e_m = ApproachWithoutPair(path, g, c.pair_stiffness, c.tip_relief, force, corner) -
                       (c.tip_relief.GapAt(g, g) - c.tip_relief.pinion_amount_m);
  if (!c.loaded_path.empty()) return;
  const bool wheel = c.tip_relief.wheel_amount_m >= c.tip_relief.pinion_amount_m;
  char rule[256];
  std::snprintf(rule, sizeof rule,
                "with this relief the tracked pair carries less than %.0f %% of F_bt = %.4g N "
                "along the whole path, or drops below it between A and E, so the mesh cycle "
                "has no loaded film to follow",
                100 * kMinFilmShare, force);
  doc.Problem(wheel ? "gear.wheel" : "gear.pinion", "tip_relief_m", rule,
              "a smaller tip_relief_m or a shorter tip_relief_length_m (the pair stays loaded "
              "to A and E below " +
                  Fmt3(c.relief_limit_a_m) + " m at the wheel and " + Fmt3(c.relief_limit_e_m) +
                  " m at the pinion)");
}

}  // namespace

double CornerMaxGap(const GearCase& c) {
  const GearPair& pair = *c.pair;
  double gap = kCornerMaxGapModules * pair.spec().module_m;
  if (!c.pair_stiffness) return gap;
  const PathOfContact path(pair, c.operating.pinion_speed_rad_s);
  double k_min = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= 50; ++i) {
    const ContactPoint p = path.At(path.length_m() * i / 50);
    k_min = std::min(k_min, c.pair_stiffness(p.r1_m, p.r2_m));
  }
  const double force = NominalToothLoad(pair, c.operating).normal_force_n;
  if (k_min > 0) gap = std::max(gap, kCornerApproachFactor * force / k_min);
  return gap;
}

double GearCase::ReducedModulusPa() const {
  return ReducedModulus(spec.pinion.material.youngs_modulus_pa, spec.pinion.material.poisson_ratio,
                        spec.wheel.material.youngs_modulus_pa, spec.wheel.material.poisson_ratio);
}

PairStiffnessFn MakePairStiffness(const GearPair& pair,
                                  const std::string& method,
                                  std::shared_ptr<const PairStiffnessModel>* owner) {
  if (method == "iso") {
    const IsoStiffness iso =
        IsoMethodB(PinionBlank(pair), WheelBlank(pair), pair.line(Flank::kDrive).contact_ratio,
                   pair.spec().helix_angle_rad);
    // A constant pair stiffness whose period mean k eps_alpha is ISO's mesh stiffness
    // c_gamma_alpha (the value ISO 6336-1 takes for the dynamics: K_v's resonance); c' is the
    // largest single-pair stiffness, which a constant pair would carry at every point.
    // [N/(mm um)] per mm of face width -> [N/m] for the whole width.
    const double eps = pair.line(Flank::kDrive).contact_ratio;
    const double k = iso.c_gamma_alpha_n_per_mm_um / eps * 1e9 * pair.spec().face_width_m;
    owner->reset();
    return [k](double, double) { return k; };
  }
  std::shared_ptr<const PairStiffnessModel> model =
      MakePairStiffnessModel(method, PinionBlank(pair), WheelBlank(pair));
  *owner = model;
  const PairStiffnessModel* raw = model.get();
  return [raw](double r1, double r2) { return raw->PairStiffness(r1, r2); };
}

std::optional<GearCase> ReadGearCase(Document& doc, bool with_dynamic_load) {
  const bool gear =
      doc.HasSection("gear") || doc.HasSection("gear.pinion") || doc.HasSection("gear.wheel");
  if (!gear) {
    // An unreadable file has been reported already; only a readable non-gear case is told.
    if (doc.problems().empty() || doc.HasSection("contact"))
      doc.Problem("gear", "", "this command needs a gear case",
                  "a case with [gear], [gear.pinion], [gear.wheel] and [operating]");
    return std::nullopt;
  }
  if (GearKeysInError(doc)) return std::nullopt;

  GearCase c;
  c.spec = ReadSpec(doc);
  c.mesh_stiffness = doc.String("gear", "mesh_stiffness");
  c.load_sharing =
      LoadSharingFromString(doc.String("gear", "load_sharing")).value_or(LoadSharing::kStiffness);
  c.tip_relief = ReadTipRelief(doc);
  const double w1 = doc.Given("operating", "pinion_speed_rpm")
                        ? RpmToRadPerS(doc.Real("operating", "pinion_speed_rpm"))
                        : doc.Real("operating", "pinion_speed_rad_s");
  c.operating.pinion_speed_rad_s = w1;
  if (doc.Given("operating", "power_w")) {
    c.power_w = doc.Real("operating", "power_w");
    c.operating.pinion_torque_nm = TorqueFromPower(c.power_w, w1);
  } else {
    c.operating.pinion_torque_nm = doc.Real("operating", "pinion_torque_nm");
    c.power_w = c.operating.pinion_torque_nm * w1;
  }
  if (doc.HasSection("motor")) {  // the pinion speed is the DC motor's operating point
    const auto w = MotorPinionSpeed(doc, "motor", c.operating.pinion_torque_nm);
    if (!w) return std::nullopt;
    c.operating.pinion_speed_rad_s = *w;
    c.power_w = c.operating.pinion_torque_nm * *w;
    c.speed_from_motor = true;
  }

  try {
    c.pair.emplace(c.spec);
  } catch (const InputError& e) {
    AddProblems(doc, e);
    return std::nullopt;
  }
  const GearPair& pair = *c.pair;
  bool geometry_ok = true;
  for (auto& p : CheckGeometry(pair)) {
    if (p.warning) {
      c.warnings.push_back(std::move(p));
    } else {
      doc.Problem(p.section, p.key, p.rule, p.allowed);
      geometry_ok = false;
    }
  }
  if (!geometry_ok) return c;

  // Pitch-line speeds of gears run from creep to about 200 m/s (turbine gears; ISO 6336-1
  // rates up to there): beyond, or at a speed so small that the load computed from the power
  // overflows, the inputs are not a gear drive.
  const double v_pitch = c.operating.pinion_speed_rad_s * pair.pinion().pitch_radius_m;
  if (!doc.HasSection("motor") &&
      !(v_pitch >= kMinPitchLineSpeed && v_pitch <= kMaxPitchLineSpeed)) {
    const bool rpm = doc.Given("operating", "pinion_speed_rpm");
    const double per_unit =
        rpm ? RpmToRadPerS(1.0) * pair.pinion().pitch_radius_m : pair.pinion().pitch_radius_m;
    doc.Problem("operating", rpm ? "pinion_speed_rpm" : "pinion_speed_rad_s",
                "the pitch-line speed " + FormatShort(v_pitch) + " m/s is outside " +
                    FormatShort(kMinPitchLineSpeed) + " ... " + FormatShort(kMaxPitchLineSpeed) +
                    " m/s, the range of gear drives",
                FormatShort(kMinPitchLineSpeed / per_unit) + " ... " +
                    FormatShort(kMaxPitchLineSpeed / per_unit) + (rpm ? " [rpm]" : " [rad/s]") +
                    " for this pinion");
    return c;
  }

  // Hertz line-contact theory needs b << R: the whole nominal tooth load at the path end with
  // the smaller R bounds b / R on the path from above.
  const PathOfContact path(pair, c.operating.pinion_speed_rad_s);
  c.loaded_path = {0.0, path.length_m()};
  const double r_min =
      std::min(path.At(0.0).reduced_radius_m, path.At(path.length_m()).reduced_radius_m);
  const double w_nominal = NominalToothLoad(pair, c.operating).load_per_width_n_per_m;
  if (r_min > 0 && w_nominal > MaxHertzLoad(r_min, c.ReducedModulusPa())) {
    const HertzScales hz = LineContactHertz(w_nominal, r_min, c.ReducedModulusPa());
    char rule[320];
    std::snprintf(rule, sizeof rule,
                  "the tooth load %.3g N/m gives a Hertz half-width b = %.3g m against R = "
                  "%.3g m at the end of the path (p_H = %.3g Pa): Hertz line-contact theory "
                  "needs b << R",
                  w_nominal, hz.half_width_m, r_min, hz.max_pressure_pa);
    const double limit = MaxHertzLoad(r_min, c.ReducedModulusPa()) / w_nominal;
    const bool power = doc.Given("operating", "power_w");
    char allowed[160];
    if (power)
      std::snprintf(allowed, sizeof allowed, "power_w <= %.3g [W] (b <= 0.2 R)",
                    c.power_w * limit);
    else
      std::snprintf(allowed, sizeof allowed, "pinion_torque_nm <= %.3g [N m] (b <= 0.2 R)",
                    c.operating.pinion_torque_nm * limit);
    doc.Problem("operating", power ? "power_w" : "pinion_torque_nm", rule, allowed);
    return c;
  }

  const double eps = pair.line(Flank::kDrive).contact_ratio;
  if (c.load_sharing == LoadSharing::kLinear && eps >= 2.0)
    doc.Problem("gear", "load_sharing",
                "the linear ramp needs 1 <= eps_alpha < 2; this pair has eps_alpha = " +
                    std::to_string(eps),
                "load_sharing = \"stiffness\"");
  // The potential-energy and Kuang-Yang models bend a spur tooth in its transverse plane; a
  // helical tooth is not such a cantilever (and its transverse blank is not that model's).
  if (pair.spec().helix_angle_rad > 0 && c.mesh_stiffness != "iso") {
    doc.Problem("gear", "helix_angle_deg",
                "the " + c.mesh_stiffness +
                    " mesh stiffness is a spur-tooth model: a helical pair's stiffness needs "
                    "the ISO 6336-1 method",
                "helix_angle_deg = 0, or mesh_stiffness = \"iso\"");
    return c;
  }
  try {
    c.pair_stiffness = MakePairStiffness(pair, c.mesh_stiffness, &c.model);
  } catch (const InputError& e) {
    AddProblems(doc, e);
  }
  if (c.load_sharing == LoadSharing::kLoaded)
    c.corner_contact = std::make_shared<const CornerContact>(pair, Flank::kDrive, CornerMaxGap(c));
  if (!CheckTipReliefKeys(doc, c, path.length_m())) return c;
  if (c.tip_relief.Active() && c.pair_stiffness) FindLoadedPath(doc, c);
  if (with_dynamic_load && doc.Bool("effects", "dynamic_load")) {
    c.dynamic_load = MakeDynamicLoad(doc, c);
    if (c.dynamic_load && !c.dynamic_load->response().periodic)
      c.warnings.push_back({"effects", "dynamic_load",
                            "torsional response " + c.dynamic_load->response().message +
                                "; its last period is used",
                            "more [dynamics] max_periods or damping_ratio", true});
  }
  return c;
}

std::vector<MeshCycleRow> GearCaseCycle(const GearCase& c, int points) {
  const PathOfContact path(*c.pair, c.operating.pinion_speed_rad_s);
  MeshCycleOptions o;
  o.points = points;
  o.load_sharing = c.load_sharing;
  o.relief = c.tip_relief;
  o.corner = c.corner_contact.get();
  std::vector<MeshCycleRow> rows =
      MeshCycle(path, NominalToothLoad(*c.pair, c.operating), o, c.pair_stiffness);
  if (c.dynamic_load)
    for (MeshCycleRow& r : rows)
      r.load_n_per_m *= c.dynamic_load->LoadFactorAt(r.contact.s_m, r.contact.s_m > 0);
  return rows;
}

}  // namespace tehl::internal

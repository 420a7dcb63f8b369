#include "scene/dynamic_load.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "base/schema.hpp"
#include "tehl/error.hpp"
#include "tehl/gear/flank_phase.hpp"
#include "tehl/gear/load_sharing.hpp"
#include "tehl/gear/operating_point.hpp"
#include "tehl/gear/path_of_contact.hpp"
#include "tehl/gear/tip_relief.hpp"

namespace tehl::internal {

DynamicsCase ReadDynamicsCase(Document& doc, const GearCase& c) {
  DynamicsCase d;
  TorsionalParameters& p = d.params;
  const GearPair& pair = *c.pair;
  // The torsional model meshes spur pairs: a pair enters along its whole face at A. Helical
  // contact lines enter gradually over the face (eps_beta), which smooths k(t) in a way the
  // model does not describe.
  if (pair.spec().helix_angle_rad > 0)
    doc.Problem("gear", "helix_angle_deg",
                "the torsional dynamics mesh spur teeth (each pair enters along its whole face "
                "at A); a helical pair's contact lines enter over the face (eps_beta = " +
                    FormatShort(pair.face_contact_ratio()) + "), which it does not model",
                "helix_angle_deg = 0 for tehl dynamics and [effects] dynamic_load");
  p.pinion_speed_rad_s = c.operating.pinion_speed_rad_s;
  p.pinion_torque_nm = c.operating.pinion_torque_nm;
  p.damping_ratio = doc.Real("dynamics", "damping_ratio");
  p.friction =
      FrictionLawFromString(doc.String("dynamics", "friction")).value_or(FrictionLaw::kNone);
  p.friction_coefficient = doc.Real("dynamics", "friction_coefficient");

  const double b = pair.spec().face_width_m;
  const char* keys[2] = {"pinion_inertia_kg_m2", "wheel_inertia_kg_m2"};
  const GearGeometry* gears[2] = {&pair.pinion(), &pair.wheel()};
  const GearMemberSpec* members[2] = {&pair.spec().pinion, &pair.spec().wheel};
  double j[2];
  for (int i = 0; i < 2; ++i) {
    d.inertia_from_blanks[i] = !doc.Given("dynamics", keys[i]);
    j[i] = d.inertia_from_blanks[i]
               ? DiscInertia(members[i]->material.density_kg_m3, b, gears[i]->pitch_radius_m)
               : doc.Real("dynamics", keys[i]);
  }
  p.pinion_inertia_kg_m2 = j[0];
  p.wheel_inertia_kg_m2 = j[1];
  if (pair.spec().internal && d.inertia_from_blanks[1])
    doc.Problem("dynamics", "wheel_inertia_kg_m2",
                "a ring gear is not a solid disc: its inertia must be given",
                "the ring's polar moment of inertia [kg m^2]");

  d.backlash_from_geometry = !doc.Given("dynamics", "backlash_m");
  p.backlash_m = d.backlash_from_geometry
                     ? (pair.backlash_m() > 1e-12 ? pair.backlash_m() : 0.0) *  // 1 pm: rounding
                           std::cos(pair.line(Flank::kDrive).working_pressure_angle_rad)
                     : doc.Real("dynamics", "backlash_m");
  // Along the line of action the backlash is the circumferential play on the working circle
  // times cos(alpha_wt), below p_w cos(alpha_wt) = p_b even for teeth of no thickness: a
  // value of a base pitch or more is no gear's, most likely millimetres written as metres.
  const double pitch = pair.line(Flank::kDrive).base_pitch_m;
  if (!d.backlash_from_geometry && p.backlash_m >= pitch)
    doc.Problem("dynamics", "backlash_m",
                "a backlash of " + FormatShort(p.backlash_m) +
                    " m along the line of action is not below the base pitch p_b = " +
                    FormatShort(pitch * 1e3) + " mm (a tooth space): in millimetres?",
                "backlash_m < " + FormatShort(pitch) +
                    " [m], in metres (0.1 mm = 1e-4; usually a few hundredths of the module)");

  // Corner contact is followed out to CornerMaxGap (gear_case.hpp; corner_contact.hpp).
  const bool corner = doc.Bool("dynamics", "corner_contact");
  if (corner) d.corner_max_gap_m = CornerMaxGap(c);
  // The film's dynamic load is the static share times the ratio of the tracked pair's
  // dynamic to quasi-static load in this model: a static sharing with corner contact and a
  // torsional model without it would apply the stepped model's spike on top of the ramp.
  if (!corner && c.load_sharing == LoadSharing::kLoaded && doc.Bool("effects", "dynamic_load"))
    doc.Problem("dynamics", "corner_contact",
                "load_sharing = \"loaded\" shares the load with corner contact; the dynamic load "
                "of the films needs the torsional model with it too",
                "corner_contact = true (the default), or load_sharing = \"stiffness\"");

  DynamicResponseOptions& o = d.options;
  o.relative_tolerance = doc.Real("dynamics", "relative_tolerance");
  o.periodic_tolerance = doc.Real("dynamics", "periodic_tolerance");
  o.max_periods = static_cast<int>(doc.Int("dynamics", "max_periods"));
  o.output_samples = static_cast<int>(doc.Int("dynamics", "output_samples"));
  if (doc.Given("dynamics", "friction_coefficient") && p.friction != FrictionLaw::kConstant)
    doc.Problem(
        "dynamics", "friction_coefficient",
        "is used only with friction = \"constant\" (friction is \"" + ToString(p.friction) + "\")",
        "friction = \"constant\", or remove friction_coefficient");
  return d;
}

std::unique_ptr<TorsionalMesh> MakeTorsionalMesh(const GearCase& c, const DynamicsCase& d) {
  auto mesh = std::make_unique<TorsionalMesh>(*c.pair, c.pair_stiffness, 33, c.tip_relief,
                                              d.corner_max_gap_m);
  // The back flanks are the coast flanks (flank_phase.hpp): the drive mesh of the pair seen
  // from its coast side, with the same relief and corner contact; for symmetric teeth that
  // pair is this one, and so is its mesh.
  std::shared_ptr<const TorsionalMesh> back;
  const GearPairSpec& spec = c.pair->spec();
  if (spec.coast_pressure_angle_rad == spec.drive_pressure_angle_rad) {
    back = std::make_shared<const TorsionalMesh>(*mesh);
  } else {
    const GearPair coast(CoastSideSpec(spec));
    std::shared_ptr<const PairStiffnessModel> owner;
    const PairStiffnessFn k = MakePairStiffness(coast, c.mesh_stiffness, &owner);
    back = std::make_shared<const TorsionalMesh>(coast, k, 33, c.tip_relief, d.corner_max_gap_m);
  }
  mesh->SetBackFlanks(std::move(back), CoastPhaseOffset(*c.pair));
  return mesh;
}

DynamicLoad::DynamicLoad(const GearCase& c, const DynamicsCase& d)
    : mesh_(MakeTorsionalMesh(c, d)), model_(std::make_unique<TorsionalModel>(*mesh_, d.params)) {
  response_ = SolvePeriodicResponse(*model_, d.options);
}

double DynamicLoad::LoadFactorAt(double s, bool left) const {
  const double pb = mesh_->base_pitch_m();
  s = std::clamp(s, 0.0, mesh_->length_m());
  double phase = s - std::floor(s / pb) * pb;
  if (left && phase < 1e-9 * pb && s > 0) phase = pb;
  if (!mesh_->gapped()) return response_.ForceAt(phase, left) / response_.static_force_n;
  // With tip relief or corner contact the shares follow the approach: the tracked pair's
  // dynamic load (its share at the dynamic x of the force) over its static load (its share
  // at the static approach of F_static).
  const double f0 = response_.static_force_n;
  const double share0 = mesh_->ShareAt(s, left, mesh_->StaticApproachAt(s, left, f0));
  const DynamicSample d = response_.SampleAt(phase, left);
  return share0 > 0 ? d.force_n * mesh_->ShareAt(s, left, d.x_m) / (share0 * f0) : 1.0;
}

namespace {

// With tip relief the mesh force may stay positive while the tracked pair lifts off: at the
// dynamic approach its relieved flank can clear. The loaded path keeps its static load above
// kMinFilmShare of F_bt; its dynamic load must stay above zero, or there is no film to solve
// (a light film in between is solved as any other). Sampled as the mesh cycle samples its
// path (400 intervals, both one-sided limits).
bool RelievedPairStaysLoaded(Document& doc, const GearCase& c, const DynamicLoad& load) {
  const PathOfContact path(*c.pair, c.operating.pinion_speed_rad_s);
  const double force = NominalToothLoad(*c.pair, c.operating).normal_force_n;
  const double g = path.length_m(), nudge = 1e-9 * g;
  const double begin = c.loaded_path.begin_m, end = c.loaded_path.end_m;
  double min_share = 1, s_min = begin;
  for (int i = 0; i <= 400; ++i) {
    const double s = begin + (end - begin) * i / 400;
    for (bool left : {true, false}) {
      const double q = left ? std::max(s - nudge, 0.0) : std::min(s + nudge, g);
      const double share =
          RelievedLoadShare(path, q, c.pair_stiffness, c.tip_relief, force, c.corner_contact.get())
              .share *
          load.LoadFactorAt(s, left);
      if (!(share >= min_share)) {
        min_share = share;
        s_min = s;
      }
    }
  }
  if (min_share > 0) return true;
  char rule[320];
  std::snprintf(rule, sizeof rule,
                "with tip relief the tracked pair lifts off under the vibration: its dynamic "
                "load falls to zero at s = %.4g mm from A (F_bt = %.4g N), and a film cannot "
                "carry zero load",
                1e3 * s_min, force);
  doc.Problem("effects", "dynamic_load", rule,
              "a smaller tip_relief_m, a larger [dynamics] damping_ratio, another speed (tehl "
              "dynamics CASE --speeds shows the dynamic factor), or dynamic_load = false");
  return false;
}

}  // namespace

std::shared_ptr<const DynamicLoad> MakeDynamicLoad(Document& doc, const GearCase& c) {
  if (!c.pair || !c.pair_stiffness) return nullptr;
  const DynamicsCase d = ReadDynamicsCase(doc, c);
  if (!doc.problems().empty()) return nullptr;
  auto load = std::make_shared<const DynamicLoad>(c, d);
  const DynamicResponse& r = load->response();
  if (!r.integrator.usable() || r.steps.empty()) {
    doc.Problem("effects", "dynamic_load",
                "the torsional dynamics at the case's speed failed: " + r.message,
                "a tighter [dynamics] relative_tolerance, more damping, or dynamic_load = false");
    return nullptr;
  }
  if (r.min_force_n <= 0 || r.separated_fraction > 0 || r.back_flank_fraction > 0) {
    char rule[256];
    std::snprintf(rule, sizeof rule,
                  "at the case's speed the drive flanks unload (min mesh force %.3g N, separated "
                  "%.1f %%, back flank %.1f %% of the mesh period): a film cannot carry zero load",
                  r.min_force_n, 100 * r.separated_fraction, 100 * r.back_flank_fraction);
    doc.Problem("effects", "dynamic_load", rule,
                "a larger [dynamics] damping_ratio, another speed (tehl dynamics CASE --speeds "
                "shows where), or dynamic_load = false");
    return nullptr;
  }
  if (c.tip_relief.Active() && !RelievedPairStaysLoaded(doc, c, *load)) return nullptr;
  return load;
}

}  // namespace tehl::internal

// Where the gear layer meets the case file: the [gear], [gear.pinion], [gear.wheel] and
// [operating] sections of a case Document turned into the gear structs and the operating
// point, with every geometric problem (interference, undercut without allow_undercut,
// eps_alpha < 1, pointed tip, overlapping or impossible centre distance, a stiffness method
// outside its range, linear load sharing with eps_alpha >= 2, a tip relief that leaves no
// loaded film) added to the Document at its key, so the user sees file:line and what to
// change. Private to src/.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/schema.hpp"
#include "tehl/gear/gear_pair.hpp"
#include "tehl/gear/geometry_checks.hpp"
#include "tehl/gear/load_sharing.hpp"
#include "tehl/gear/mesh_cycle.hpp"
#include "tehl/gear/mesh_stiffness.hpp"
#include "tehl/gear/operating_point.hpp"
#include "tehl/gear/tip_relief.hpp"

namespace tehl::internal {

class DynamicLoad;  // scene/dynamic_load.hpp

// A relief can lift the tracked pair off near A and E; its films are solved where it carries
// at least this share of F_bt (below it the film is near-rigid and its load negligible) [-].
inline constexpr double kMinFilmShare = 0.01;
// The pitch-line speeds a gear case accepts [m/s].
inline constexpr double kMinPitchLineSpeed = 1e-6;
inline constexpr double kMaxPitchLineSpeed = 200.0;

// How far corner contact is followed beyond A and E: to a separation of this many normal
// modules (0.1 mm at m_n = 2 mm, some ten times the static approach of ordinary gears) [-],
// and at least kCornerApproachFactor times the approach of the softest single pair under
// F_bt (dynamic approaches reach a few times the static one near resonance) [-].
inline constexpr double kCornerMaxGapModules = 0.05;
inline constexpr double kCornerApproachFactor = 10.0;

struct GearCase;
// The separation to which the case's corner contact is followed [m] (the larger of the two
// rules above; needs the pair and its pair stiffness).
double CornerMaxGap(const GearCase& c);

struct GearCase {
  GearPairSpec spec;
  std::optional<GearPair> pair;  // empty when the spec is unusable
  OperatingPoint operating;      // pinion speed and torque
  double power_w = 0;            // P = T1 w1 [W]
  bool speed_from_motor = false;  // the pinion speed is the [motor]'s operating point
  LoadSharing load_sharing = LoadSharing::kStiffness;
  TipRelief tip_relief;        // [gear.pinion] / [gear.wheel] tip_relief_m, _length_m
  // Where the tracked pair carries at least kMinFilmShare of F_bt: the films of the mesh
  // cycle are solved from begin to end ([0, g_alpha] without relief) [m].
  LoadedPath loaded_path;
  // With relief: the largest wheel (pinion) amount that keeps the pair loaded to A (E) at
  // this load, the other relief as it is [m].
  double relief_limit_a_m = 0, relief_limit_e_m = 0;
  std::string mesh_stiffness;  // "potential_energy" | "kuang_yang" | "iso"
  // The pair stiffness of mesh_stiffness; for "iso" a constant c' b (ISO 6336-1 method B
  // gives no variation along the path). Empty when the method could not be built.
  PairStiffnessFn pair_stiffness;
  std::shared_ptr<const PairStiffnessModel> model;  // owner behind pair_stiffness
  // load_sharing = "loaded": the pair's corner contact beyond A and E (corner_contact.hpp),
  // followed to a separation of kCornerMaxGapModules m_n. Null otherwise.
  std::shared_ptr<const CornerContact> corner_contact;
  std::vector<GeometryProblem> warnings;            // geometry warnings, for the report
  // [effects] dynamic_load: the periodic torsional response at the case's speed; the cycle's
  // w(s) is the static w(s) times its LoadFactorAt(s). Null when the effect is off.
  std::shared_ptr<const DynamicLoad> dynamic_load;

  double ReducedModulusPa() const;  // E' of the two gear materials [Pa]
};

// Builds the gear case from a document read by ReadCaseDocument. Problems go into `doc`
// (call doc.ThrowIfProblems() afterwards). Returns nothing when the document has no gear
// pair or its gear keys are already in error. `with_dynamic_load` = false leaves out the
// `dynamic_load` effect (the films' dynamic load and its checks): `tehl dynamics` solves the
// torsional model itself, at any speed, also where the films could not carry the load.
std::optional<GearCase> ReadGearCase(Document& doc, bool with_dynamic_load = true);

// The stiffness of one pair by `method` for this pair; throws InputError (key
// gear.mesh_stiffness) when the method does not apply. "iso": constant c' b.
PairStiffnessFn MakePairStiffness(const GearPair& pair,
                                  const std::string& method,
                                  std::shared_ptr<const PairStiffnessModel>* owner);

// The mesh cycle of the case (drive flank), `points` samples from A to E.
std::vector<MeshCycleRow> GearCaseCycle(const GearCase& c, int points);

}  // namespace tehl::internal

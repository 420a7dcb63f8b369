// Where the torsional dynamics (drive layer) meets a gear case: the [dynamics] section read
// into the model's parameters, and the dynamic tooth load that replaces the static load
// sharing of the mesh cycle when [effects] dynamic_load = true (docs/dynamics.md).
//
// At the case's speed the periodic response gives the dynamic mesh force F(phi) over one
// mesh period; the tracked pair carries its share of it:
//   w_dyn(s) = share(s) F(phi(s)) / b = share(s) w_nominal F(phi(s)) / F_s,
// share(s) the case's load sharing (stiffness or linear), phi(s) = s mod p_b, so
// w_dyn / w_static = F / F_s at every s. Private to src/.
#pragma once

#include <memory>
#include <string>

#include "base/schema.hpp"
#include "scene/gear_case.hpp"
#include "tehl/drive/dynamic_response.hpp"
#include "tehl/drive/torsional_mesh.hpp"
#include "tehl/drive/torsional_model.hpp"

namespace tehl::internal {

struct DynamicsCase {
  TorsionalParameters params;  // at the case's speed and torque
  DynamicResponseOptions options;
  bool inertia_from_blanks[2] = {true, true};  // pinion, wheel: solid discs (not given)
  bool backlash_from_geometry = true;          // backlash_m not given
  // Corner contact outside [A, E] (corner_contact.hpp) up to this separation [m]; 0: off.
  double corner_max_gap_m = 0;
};

// Reads [dynamics] (defaults when absent) for the gear case `c`; problems go into `doc`.
// Inertias not given: solid discs of the pitch diameter, the face width and the member's
// density (J = pi rho b r^4 / 2). Backlash not given: the pair's circumferential backlash at
// its centre distance times cos(alpha_wt) (along the line of action), 0 at the zero-backlash
// distance.
DynamicsCase ReadDynamicsCase(Document& doc, const GearCase& c);

// The torsional mesh of the case (its stiffness method, drive flanks).
std::unique_ptr<TorsionalMesh> MakeTorsionalMesh(const GearCase& c, const DynamicsCase& d);

// The periodic response at the case's speed, kept for the mesh cycle.
class DynamicLoad {
 public:
  // Solves the periodic response. `c` must have a pair and a pair stiffness.
  DynamicLoad(const GearCase& c, const DynamicsCase& d);
  DynamicLoad(const DynamicLoad&) = delete;
  DynamicLoad& operator=(const DynamicLoad&) = delete;

  // F(phi(s)) / F_s at s from A; `left` takes the limit from below at a stiffness jump [-].
  double LoadFactorAt(double s_m, bool left) const;
  const DynamicResponse& response() const { return response_; }
  const TorsionalModel& model() const { return *model_; }
  const TorsionalMesh& mesh() const { return *mesh_; }

 private:
  std::unique_ptr<TorsionalMesh> mesh_;
  std::unique_ptr<TorsionalModel> model_;
  DynamicResponse response_;
};

// Builds the dynamic load of a case whose [effects] dynamic_load is true (ReadGearCase calls
// it). Problems (an invalid [dynamics] key, an integrator failure) go into `doc`; returns
// null then.
std::shared_ptr<const DynamicLoad> MakeDynamicLoad(Document& doc, const GearCase& c);

}  // namespace tehl::internal

// The plan of a mesh-cycle run, shared by `tehl run` and `tehl case --check`: the path and
// load of a gear case at any s (CyclePath), the film grid around the largest Hertz half-width
// on the path, and the step positions from A to E (DESIGN.md section 6).
#pragma once

#include <string>
#include <vector>

#include "base/schema.hpp"
#include "scene/film_case.hpp"
#include "scene/gear_case.hpp"
#include "tehl/ehl/grid.hpp"
#include "tehl/gear/path_of_contact.hpp"

namespace tehl::internal {

// The path and load of the case at one position s; `left` takes the one-sided limit from
// below at the switch points B and D (the load arriving there).
struct PathState {
  ContactPoint contact;
  double load_n_per_m = 0;         // the film's load (dynamic when dynamic_load is on) [N/m]
  double static_load_n_per_m = 0;  // the static load sharing [N/m]
};

class CyclePath {
 public:
  explicit CyclePath(const GearCase& c);
  const PathOfContact& path() const { return path_; }
  PathState At(double s, bool left) const;

 private:
  const GearCase& gear_;
  PathOfContact path_;
  double w_nominal_;       // F_bt / b [N/m]
  double normal_force_n_;  // F_bt [N]
};

// The ends of the segments A-B, B-D, D-E (only those inside the path), ascending [m].
std::vector<double> SegmentEnds(double g, double sb, double sd);

struct MeshCyclePlan {
  double max_half_width_m = 0;  // b_max over the path [m]
  UniformGrid grid;             // x_start_b .. x_end_b in GridUnitsFor lengths
  std::vector<double> s_steps;  // step positions from A (0) to E (g_alpha) [m]
  std::string step_rule;        // how the step count was chosen, for the run's report
};

// Plans the run; a user step count below what moving roughness needs (dt <= dx/um) is
// reported to `doc` as a problem of [numerics] steps.
MeshCyclePlan PlanMeshCycle(Document& doc, const CyclePath& cycle, double e_prime_pa,
                            const FilmCase& film);

}  // namespace tehl::internal

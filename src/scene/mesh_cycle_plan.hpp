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
  // The part of the path whose films are solved: where the tracked pair carries at least
  // kMinFilmShare of F_bt (A..E without tip relief) [m].
  double begin_m() const { return begin_m_; }
  double end_m() const { return end_m_; }

 private:
  const GearCase& gear_;
  PathOfContact path_;
  double begin_m_, end_m_;  // [m]
  double w_nominal_;       // F_bt / b [N/m]
  double normal_force_n_;  // F_bt [N]
};

// The ends of the segments A-B, B-D, D-E within [begin, end] (only the switch points inside
// it), ascending, the last being `end` (g when negative) [m].
std::vector<double> SegmentEnds(
    double g, double sb, double sd, double begin = 0.0, double end = -1.0);

struct MeshCyclePlan {
  double max_half_width_m = 0;  // b_max over the path [m]
  UniformGrid grid;             // x_start_b .. x_end_b in GridUnitsFor lengths
  std::vector<double> s_steps;  // step positions from A' to E' (A = 0 to E = g_alpha) [m]
  std::string step_rule;        // how the step count was chosen, for the run's report
  std::string grid_rule;        // how the node count was chosen (automatic_grid.hpp)
  std::string inlet_note;       // GridChoice::InletNote: "" or the inlet's estimated cost
  std::vector<std::string> input_notes;  // InputNotes (film_case.hpp)
};

// Plans the run; a user step count below what moving roughness needs (dt <= dx/um) is
// reported to `doc` as a problem of [numerics] steps.
MeshCyclePlan PlanMeshCycle(Document& doc, const CyclePath& cycle, double e_prime_pa,
                            const FilmCase& film);

}  // namespace tehl::internal

// The inputs of a plain [contact] case (two discs or rollers, or a roller on a plane): radii,
// E', and the load and speed tables, read and checked (exit 2 on a problem, docs/case_format.md).
#pragma once

#include <string>
#include <vector>

#include "base/schema.hpp"
#include "scene/film_case.hpp"
#include "tehl/ehl/grid.hpp"

namespace tehl::internal {

struct ContactInputs {
  double r1 = 0, r2 = 0;             // radii; r2 = 0 means a plane [m]
  double e_prime = 0;                // [Pa]
  std::vector<double> t, w, u1, u2;  // tables (size 1 for a steady run) [s, N/m, m/s, m/s]
  int steps = 0;
  double ReducedRadius() const { return r2 > 0 ? r1 * r2 / (r1 + r2) : r1; }
};

// Reads [contact]; speeds that do not entrain, loads <= 0 and loads beyond Hertz line-contact
// theory (b > 0.2 R) are reported to `doc`.
ContactInputs ReadContact(Document& doc);

// Reports a table row whose Martin film exceeds kMaxFilmToRadius R (film_case.hpp) at its
// load key.
void CheckFilmScale(Document& doc, const ContactInputs& in, const FilmCase& film);

// The film grid of a [contact] run: x in units of the largest Hertz half-width over the tables
// (elastic solids) or the longest rigid inlet scale (GridUnitsFor), with the case's node count
// or one that spans every table row's Hertzian edge (automatic_grid.hpp).
struct ContactGridPlan {
  UniformGrid grid;
  std::string rule;        // how the node count was chosen
  std::string inlet_note;  // GridChoice::InletNote: "" or the inlet's estimated cost
  std::vector<std::string> input_notes;  // InputNotes (film_case.hpp)
};
// Reports to `doc` what the grid cannot carry: roughness it does not resolve
// (CheckRoughnessResolution, CheckContactRoughSteps) and profiles beyond the machine's memory
// (profile_memory.hpp).
ContactGridPlan PlanContactGrid(Document& doc, const ContactInputs& in, const FilmCase& film);

// Moving roughness needs time steps that move the surfaces by at most one grid cell, dt um
// <= dx, as a mesh cycle's (mesh_cycle_plan.cpp): a transient rough case with fewer `steps`
// is reported at [contact] steps with the count it needs.
void CheckContactRoughSteps(Document& doc,
                            const ContactInputs& in,
                            const FilmCase& film,
                            double dx_m);

}  // namespace tehl::internal

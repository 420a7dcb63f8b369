// The film side of a case: lubricant, effects, numerics and surfaces read from a case
// Document into the ehl solver's inputs. Shared by the [contact] scene and, later, the
// mesh cycle. Private to src/.
#pragma once

#include <memory>
#include <string>

#include "base/schema.hpp"
#include "tehl/ehl/film_effects.hpp"
#include "tehl/ehl/line_contact_solver.hpp"
#include "tehl/ehl/surface_roughness.hpp"
#include "tehl/lubricant/lubricant.hpp"

namespace tehl::internal {

struct FilmCase {
  std::shared_ptr<const Lubricant> lubricant;     // empty if it could not be read
  double inlet_temperature_k = 0;                 // T0 of the run [K]
  FilmEffects effects;
  LineContactSolver::Options options;
  int grid_points = 513;                          // [-]
  double x_start_b = -4.5, x_end_b = 1.5;         // grid ends in Hertz half-widths [-]
  std::shared_ptr<const SurfaceShape> surface1, surface2;  // null = smooth
  ContactSolids solids;                           // thermal properties of the two bodies
};

// Reads [lubricant], [effects], [numerics] and [surfaces]; problems go into `doc`.
// Effects this version cannot simulate yet are problems at their key, never ignored.
FilmCase ReadFilmCase(Document& doc);

}  // namespace tehl::internal

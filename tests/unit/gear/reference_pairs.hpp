// Gear pairs of VALIDATION.md section 5, shared by the gear tests.
#pragma once

#include "tehl/gear/gear_pair.hpp"
#include "tehl/units.hpp"

namespace tehl::testing {

// Seed 004 Table 1: 35/105 teeth, m = 2 mm, 20 deg, b = 25 mm, standard, no shift;
// UNS C61300 (VALIDATION.md section 5: E = 117 GPa, nu = 0.34).
inline GearPairSpec Seed004Spec() {
  GearPairSpec s;
  s.pinion.teeth = 35;
  s.wheel.teeth = 105;
  s.module_m = 2e-3;
  s.face_width_m = 25e-3;
  for (GearMemberSpec* m : {&s.pinion, &s.wheel}) {
    m->material.youngs_modulus_pa = 117e9;
    m->material.poisson_ratio = 0.34;
  }
  return s;
}

// An internal pair for hand calculations (contact_ratio_test.cpp works it out): pinion
// z1 = 20 in a ring z2 = 60, m = 3 mm, 20 deg, no shift, ring tip radius 88 mm (ring
// addendum shortened to 2 mm so its tip stays clear of the pinion's fillet).
inline GearPairSpec InternalSpec() {
  GearPairSpec s = Seed004Spec();
  s.internal = true;
  s.pinion.teeth = 20;
  s.wheel.teeth = 60;
  s.module_m = 3e-3;
  s.wheel.tip_radius_m = 88e-3;
  return s;
}

// FZG type C (ISO 14635-1, VALIDATION.md section 5): 16/24, m = 4.5 mm, 20 deg,
// x = 0.1817/0.1715, a = 91.5 mm, b = 14 mm, tip radii 41.318/59.272 mm, steel.
inline GearPairSpec FzgCSpec() {
  GearPairSpec s;
  s.pinion.teeth = 16;
  s.wheel.teeth = 24;
  s.module_m = 4.5e-3;
  s.face_width_m = 14e-3;
  s.pinion.profile_shift = 0.1817;
  s.wheel.profile_shift = 0.1715;
  s.center_distance_m = 91.5e-3;
  s.pinion.tip_radius_m = 41.318e-3;
  s.wheel.tip_radius_m = 59.272e-3;
  return s;
}

// Seed 000 section 7.3 (extraction, derived): 36/36 teeth, P = 8 /in (m = 3.175 mm),
// AGMA full depth, tip radius R_o = 2.375 in for both; drive/coast angles as given.
inline GearPairSpec Seed000Spec(double drive_deg, double coast_deg) {
  GearPairSpec s;
  s.pinion.teeth = 36;
  s.wheel.teeth = 36;
  s.module_m = 25.4e-3 / 8.0;
  s.face_width_m = 25.4e-3;
  s.drive_pressure_angle_rad = DegToRad(drive_deg);
  s.coast_pressure_angle_rad = DegToRad(coast_deg);
  s.root_fillet_coefficient = 0.15;  // fits the 35/20 basic rack (max 0.197 m)
  s.pinion.tip_radius_m = s.wheel.tip_radius_m = 2.375 * 25.4e-3;
  return s;
}

}  // namespace tehl::testing

// Design rules of a simple planetary set, sun - N equally spaced planets - ring, standard
// gears (seed 001 section 2.3; addendum h_a = h_a* m):
//   coaxial condition        z_ring = z_sun + 2 z_planet                          (2.14)
//   equal spacing (assembly) N = (z_sun + z_ring) / c with c an integer           (2.12)
//   tip clearance            adjacent planet tips must not touch: 2 a sin(pi/N) > d_a,p with
//                            a = m (z_s + z_p)/2, d_a,p = m (z_p + 2 h_a*), so
//                            N < 180 deg / asin[(z_p + 2 h_a*) / (z_s + z_p)]     (2.13)
// The module cancels. For a non-standard (profile-shifted) planet the document uses the
// coaxial equivalent z_p = (z_ring - z_sun)/2 in (2.13) (Example 2.13): so does this code,
// always, and `coaxial` tells whether the given planet is standard.
#pragma once

#include <optional>
#include <vector>

namespace tehl {

struct PlanetarySet {
  int sun_teeth = 0;                  // z_s [-]
  int ring_teeth = 0;                 // z_r [-], > z_s + 2
  std::optional<int> planet_teeth;    // z_p as made; absent = standard, (z_r - z_s)/2 [-]
  double addendum_coefficient = 1.0;  // h_a* = addendum / module [-]
};

struct PlanetRules {
  double coaxial_planet_teeth = 0;  // (z_r - z_s)/2, eq. (2.14) [-]
  bool coaxial = true;              // the planet as made satisfies (2.14)
  double clearance_limit = 0;       // 180 deg / asin[(z_p + 2 h_a*)/(z_s + z_p)] [-]
  int max_by_clearance = 0;         // largest N strictly below clearance_limit [-]
  std::vector<int> equally_spaced;  // N <= max_by_clearance dividing z_s + z_r, ascending
  int max_planets = 0;              // the largest of equally_spaced [-]
  int total_teeth = 0;              // z_s + z_r [-]
  bool Assembles(int n) const;      // (z_s + z_r)/n is an integer
  bool Clears(int n) const;         // n <= max_by_clearance
};

// Throws InputError (keys sun_teeth, ring_teeth, planet_teeth, addendum_coefficient) for a
// set that cannot exist: teeth < 1, z_r <= z_s + 2, a planet whose tip circle does not fit.
PlanetRules CheckPlanetRules(const PlanetarySet& set);

}  // namespace tehl

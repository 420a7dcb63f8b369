// Design rules of a simple planetary set, sun - N equally spaced planets - ring, standard
// gears (seed 001 section 2.3; addendum h_a = h_a* m):
//   coaxial condition        z_ring = z_sun + 2 z_planet                          (2.14)
//   equal spacing (assembly) N = (z_sun + z_ring) / c with c an integer           (2.12)
//   tip clearance            adjacent planet tips must not touch: 2 a sin(pi/N) > d_a,p with
//                            a = m (z_s + z_p)/2, d_a,p = m (z_p + 2 h_a*), so
//                            N < 180 deg / asin[(z_p + 2 h_a*) / (z_s + z_p)]     (2.13)
// The module cancels. For a non-standard (profile-shifted) planet the document uses the
// coaxial equivalent z_p = (z_ring - z_sun)/2 in (2.13) (Example 2.13): so does this code,
// always, and `coaxial` tells whether the given planet is standard. A planet as made
// differs from that equivalent by the difference of its two centre distances in modules,
// m |z_p - (z_r - z_s)/2|, which the profile shifts of the two meshes have to bridge
// (Example 2.13: half a module). Shift coefficients of about -0.5 ... +1 per gear bridge at
// most about kMaxPlanetShiftModules; a planet further from the equivalent does not fit
// between its sun and ring.
#pragma once

#include <optional>
#include <vector>

namespace tehl {

// The largest |z_p - (z_r - z_s)/2| accepted for a profile-shifted planet [modules].
inline constexpr double kMaxPlanetShiftModules = 2.0;

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
// set that cannot exist: teeth < 1, z_r <= z_s + 2, a planet more than
// kMaxPlanetShiftModules from the coaxial one.
PlanetRules CheckPlanetRules(const PlanetarySet& set);

}  // namespace tehl

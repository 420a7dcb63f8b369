// Planet count rules of seed 001 section 2.3 (planet_design.hpp).
#include "tehl/drive/planet_design.hpp"

#include <cmath>
#include <string>

#include "tehl/error.hpp"
#include "tehl/units.hpp"

namespace tehl {
namespace {

// A multiple of 1/2 as "18" or "18.5".
std::string Half(double x) {
  const long twice = std::lround(2 * x);
  return std::to_string(twice / 2) + (twice % 2 ? ".5" : "");
}

}  // namespace

bool PlanetRules::Assembles(int n) const { return n > 0 && total_teeth % n == 0; }

bool PlanetRules::Clears(int n) const { return n >= 1 && n <= max_by_clearance; }

PlanetRules CheckPlanetRules(const PlanetarySet& set) {
  ProblemList p;
  const std::string zs = std::to_string(set.sun_teeth), zr = std::to_string(set.ring_teeth);
  if (set.sun_teeth < 1) p.Add({"", 0, "sun_teeth", zs, "must be >= 1", "an integer >= 1"});
  if (set.ring_teeth <= set.sun_teeth + 2)
    p.Add({"", 0, "ring_teeth", zr, "leaves no room for a planet (z_ring <= z_sun + 2)",
           "z_ring > z_sun + 2, coaxial planet (z_ring - z_sun)/2"});
  if (set.planet_teeth && *set.planet_teeth < 1)
    p.Add({"", 0, "planet_teeth", std::to_string(*set.planet_teeth), "must be >= 1",
           "an integer >= 1"});
  if (!(set.addendum_coefficient > 0 && set.addendum_coefficient < 2))
    p.Add({"", 0, "addendum_coefficient", std::to_string(set.addendum_coefficient), "out of range",
           "0 < h_a* < 2 (standard 1)"});
  p.ThrowIfAny();
  const double coaxial = 0.5 * (set.ring_teeth - set.sun_teeth);
  if (set.planet_teeth && std::abs(*set.planet_teeth - coaxial) > kMaxPlanetShiftModules) {
    const std::string zp = std::to_string(*set.planet_teeth);
    const std::string zc = Half(coaxial);
    p.Add({"", 0, "planet_teeth", zp,
           "does not fit between sun " + zs + " and ring " + zr + ": the coaxial planet has " + zc +
               " teeth, so its centre distances to sun and ring differ by " +
               Half(std::abs(*set.planet_teeth - coaxial)) +
               " modules, more than profile shift bridges (seed 001 eq. 2.14)",
           "|z_planet - (z_ring - z_sun)/2| <= " + Half(kMaxPlanetShiftModules) +
               " (standard: z_planet = " + zc + ")"});
    p.ThrowIfAny();
  }

  PlanetRules r;
  r.total_teeth = set.sun_teeth + set.ring_teeth;
  r.coaxial_planet_teeth = 0.5 * (set.ring_teeth - set.sun_teeth);
  r.coaxial = !set.planet_teeth || 2 * *set.planet_teeth == set.ring_teeth - set.sun_teeth;
  // (2.13) with the coaxial planet (Example 2.13 uses it for a non-standard planet).
  const double zp = r.coaxial_planet_teeth;
  const double x = (zp + 2 * set.addendum_coefficient) / (set.sun_teeth + zp);
  r.clearance_limit = x >= 1 ? 2.0 : kPi / std::asin(x);
  // Largest integer strictly below the limit: tips that just touch do not clear, and a limit
  // that is an integer up to round-off (5.999999999999999) is that integer.
  const double whole = std::round(r.clearance_limit);
  if (std::abs(r.clearance_limit - whole) < 1e-9 * r.clearance_limit) r.clearance_limit = whole;
  r.max_by_clearance = static_cast<int>(std::ceil(r.clearance_limit)) - 1;
  if (r.max_by_clearance < 1) r.max_by_clearance = 1;
  for (int n = 1; n <= r.max_by_clearance; ++n)
    if (r.total_teeth % n == 0) r.equally_spaced.push_back(n);
  r.max_planets = r.equally_spaced.empty() ? 1 : r.equally_spaced.back();
  return r;
}

}  // namespace tehl

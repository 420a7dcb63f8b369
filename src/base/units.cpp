#include "tehl/units.hpp"

#include <cmath>

namespace tehl {

HertzScales LineContactHertz(double w, double r, double e_prime) {
  HertzScales h;
  h.reduced_radius_m = r;
  h.half_width_m = std::sqrt(8.0 * w * r / (kPi * e_prime));
  h.max_pressure_pa = std::sqrt(w * e_prime / (2.0 * kPi * r));
  return h;
}

double MaxHertzLoad(double r, double e_prime) {
  // b = sqrt(8 w R / (pi E')) = k R  <=>  w = k^2 pi E' R / 8.
  return kMaxHertzWidthRatio * kMaxHertzWidthRatio * kPi * e_prime * r / 8.0;
}

DimensionlessGroups LineContactGroups(double eta0, double alpha, double um, double w, double r,
                                      double e_prime) {
  DimensionlessGroups g;
  g.U = eta0 * um / (e_prime * r);
  g.G = alpha * e_prime;
  g.W = w / (e_prime * r);
  g.M = g.W * std::pow(2.0 * g.U, -0.5);
  g.L = g.G * std::pow(2.0 * g.U, 0.25);
  return g;
}

}  // namespace tehl

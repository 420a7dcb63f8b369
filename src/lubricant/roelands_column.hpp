// Roelands-type laws over a film column or a grid: the pressure factor (1 + p/p0)^Z computed
// once per run of equal pressures (the nodes across a film share it), the temperature factor
// once per run of equal temperatures.
// Private to src/lubricant.
#pragma once

#include <cmath>

#include "tehl/lubricant/viscosity_model.hpp"

namespace tehl::internal {

// out[i] = finish(base, base^z, T[i], tf) with base = 1 + scale p[i] and tf =
// temperature_factor(T[i]); the same operations as a point-by-point evaluation, so the
// values are identical. Both factors are recomputed only when p or T changes from the
// previous point (a column shares p; an isothermal grid shares T).
template <class TemperatureFactor, class Finish>
void EvaluateColumn(const double* p_pa,
                    const double* t_k,
                    int n,
                    double scale_per_pa,
                    double z,
                    const TemperatureFactor& temperature_factor,
                    const Finish& finish,
                    ViscosityValue* out) {
  double last_p = 0, base = 1, pz = 1, last_t = 0, tf = 0;
  bool have_p = false, have_t = false;
  for (int i = 0; i < n; ++i) {
    if (!have_p || p_pa[i] != last_p) {
      last_p = p_pa[i];
      base = 1.0 + scale_per_pa * last_p;
      pz = std::pow(base, z);
      have_p = true;
    }
    if (!have_t || t_k[i] != last_t) {
      last_t = t_k[i];
      tf = temperature_factor(last_t);
      have_t = true;
    }
    out[i] = finish(base, pz, t_k[i], tf);
  }
}

}  // namespace tehl::internal

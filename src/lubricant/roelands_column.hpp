// Roelands-type laws over a film column: the pressure factor (1 + p/p0)^Z computed once per
// distinct pressure (the nodes across a film share it), the temperature part per point.
// Private to src/lubricant.
#pragma once

#include <cmath>

#include "tehl/lubricant/viscosity_model.hpp"

namespace tehl::internal {

// out[i] = finish(base, base^z, T[i]) with base = 1 + scale p[i]; the same operations as a
// point-by-point evaluation, so the values are identical.
template <class Finish>
void EvaluateColumn(const double* p_pa,
                    const double* t_k,
                    int n,
                    double scale_per_pa,
                    double z,
                    const Finish& finish,
                    ViscosityValue* out) {
  double last_p = 0, base = 1, pz = 1;
  bool have = false;
  for (int i = 0; i < n; ++i) {
    if (!have || p_pa[i] != last_p) {
      last_p = p_pa[i];
      base = 1.0 + scale_per_pa * last_p;
      pz = std::pow(base, z);
      have = true;
    }
    out[i] = finish(base, pz, t_k[i]);
  }
}

}  // namespace tehl::internal

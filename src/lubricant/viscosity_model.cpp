#include "tehl/lubricant/viscosity_model.hpp"

namespace tehl {

void ViscosityModel::EvaluateMany(const double* p_pa,
                                  const double* T_k,
                                  int n,
                                  ViscosityValue* out) const {
  for (int i = 0; i < n; ++i) out[i] = Evaluate(p_pa[i], T_k[i]);
}

}  // namespace tehl

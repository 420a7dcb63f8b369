#include "tehl/lubricant/density_model.hpp"

namespace tehl {

void DensityModel::EvaluateMany(const double* p_pa,
                                const double* T_k,
                                int n,
                                DensityValue* out) const {
  for (int i = 0; i < n; ++i) out[i] = Evaluate(p_pa[i], T_k[i]);
}

}  // namespace tehl

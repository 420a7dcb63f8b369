#include "tehl/gear/mesh_stiffness.hpp"

#include "gear/stiffness_blank_check.hpp"
#include "tehl/error.hpp"
#include "tehl/gear/kuang_yang_stiffness.hpp"
#include "tehl/gear/potential_energy_stiffness.hpp"

namespace tehl {

std::unique_ptr<PairStiffnessModel> MakePairStiffnessModel(const std::string& method,
                                                           const ToothBlank& pinion,
                                                           const ToothBlank& wheel) {
  if (method == "potential_energy") {
    return std::make_unique<PotentialEnergyStiffness>(pinion, wheel);
  }
  if (method == "kuang_yang") {
    return std::make_unique<KuangYangStiffness>(pinion, wheel);
  }
  throw InputError(internal::MethodRangeProblem("\"" + method + "\"",
                                                "unknown pair stiffness method",
                                                "\"potential_energy\", \"kuang_yang\""));
}

}  // namespace tehl

// Uses only the installed public headers and library: reads the installed SAE 40 file and
// computes the Hertz scales of the seed 004 pitch point (VALIDATION.md section 5).
#include <cmath>
#include <cstdio>
#include <string>

#include "tehl/error.hpp"
#include "tehl/lubricant/lubricant.hpp"
#include "tehl/units.hpp"

int main() {
  try {
    const tehl::Lubricant oil =
        tehl::Lubricant::FromFile(std::string(TEHL_LUBRICANT_DIR) + "/sae40.toml");
    // Seed 004 Table 2: eta0 = 0.1140574 Pa s at T0 = 313.15 K.
    if (oil.viscosity().ReferenceViscosity() != 0.1140574) {
      std::fprintf(stderr, "unexpected eta0 %g\n", oil.viscosity().ReferenceViscosity());
      return 1;
    }
    // VALIDATION.md section 5: R = 8.978 mm, w = 116.14 kN/m, UNS C61300 (117 GPa, 0.34)
    // -> p_H ~ 522 MPa, b ~ 142 um.
    const double e_prime = tehl::ReducedModulus(117e9, 0.34, 117e9, 0.34);
    const tehl::HertzScales h = tehl::LineContactHertz(116.14e3, 8.978e-3, e_prime);
    std::printf("%s: eta0 = %g Pa s; p_H = %.1f MPa, b = %.1f um\n", oil.name().c_str(),
                oil.viscosity().ReferenceViscosity(), h.max_pressure_pa * 1e-6,
                h.half_width_m * 1e6);
    if (std::abs(h.max_pressure_pa - 522e6) > 2e6 || std::abs(h.half_width_m - 142e-6) > 1e-6)
      return 1;
  } catch (const tehl::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}

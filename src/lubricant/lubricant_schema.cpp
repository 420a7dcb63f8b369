#include "lubricant/lubricant_schema.hpp"

#include "tehl/lubricant/model_factory.hpp"

namespace tehl::internal {
namespace {

// Keys of a law's parameters carry no default: the chosen model makes them required, and
// keys it does not read are errors (model_factory.cpp).
Schema BuildLubricantSchema() {
  Schema s;
  s.kind = "lubricant";
  s.sections = {
      {"",
       "the oil and where its data come from",
       true,
       {
           Required(Text("name", "", "display name, e.g. \"SAE 40 mineral oil\""),
                    "\"SAE 40 mineral oil\""),
           Required(Text("source", "", "citation of the data: paper, table, temperature range"),
                    "\"Panichakorn & Mongkolwongroj, Table 2\""),
           Required(Temperature("reference_temperature_k", "",
                                "T0 at which density_kg_m3 and viscosity_pa_s are given"),
                    "313.15"),
       }},
      {"density",
       "density law rho(p, T)",
       true,
       {
           Required(Text("model", "", "density law", DensityLawNames()), "\"dowson_higginson\""),
           Real("density_kg_m3", "kg/m^3", "", "rho0 at p = 0 and T0 (all models)", 300.0, 3000.0),
           Real("expansivity_per_k", "1/K", "", "thermal expansivity beta (dowson_higginson)", 0.0,
                0.01, true, false),
       }},
      {"viscosity",
       "viscosity law eta(p, T)",
       true,
       {
           Required(Text("model", "", "viscosity law", ViscosityLawNames()), "\"roelands_gamma\""),
           Real("viscosity_pa_s", "Pa s", "", "eta0 at p = 0 and T0 (all models)", 0.0, 1e4, false,
                true),
           Real("pressure_index", "-", "",
                "Roelands pressure-viscosity index Z (roelands, "
                "roelands_gamma)",
                0.0, 1.5, false, true),
           Real("temperature_index", "-", "", "Roelands temperature index S0 (roelands)", 0.0, 5.0,
                false, true),
           Real("temperature_coefficient_per_k", "1/K", "",
                "viscosity-temperature coefficient "
                "gamma = -d ln(eta)/dT (roelands_gamma, barus)",
                0.0, 1.0),
           Real("pressure_coefficient_per_pa", "1/Pa", "",
                "pressure-viscosity coefficient "
                "alpha (barus)",
                0.0, 1e-7),
       }},
      {"thermal",
       "thermal conductivity law k(p) and heat capacity",
       true,
       {
           Required(Text("conductivity_model", "", "conductivity law", ConductivityLawNames()),
                    "\"pressure_dependent\""),
           Required(Real("conductivity_w_mk", "W/(m K)", "", "k0 at p = 0", 0.0, 10.0, false),
                    "0.125"),
           Required(Real("heat_capacity_j_kgk", "J/(kg K)", "", "specific heat capacity c_p", 100.0,
                         10000.0),
                    "1900.0"),
       }},
      {"eyring",
       "Ree-Eyring shear thinning; needed for effects.non_newtonian",
       false,
       {
           // Measured Eyring stresses of oils lie between about 0.1 and 20 MPa (Bair & Winer
           // 1979; Johnson & Tevaarwerk 1977); below 1 kPa the film would be all shear thinning.
           Required(Real("eyring_stress_pa", "Pa", "", "Eyring stress tau_0", 1e3, 1e9), "5e6"),
           Real(
               "limiting_stress_pa", "Pa", "0.0",
               "limiting shear stress tau_L0 at p = 0 (0 with slope 0: no limit; > 0 with a slope)",
               0.0, 1e10),
           Real("limiting_stress_slope", "-", "0.0",
                "Lambda = d tau_L / d p of tau_L = tau_L0 + Lambda p (> 0 needs tau_L0 > 0)", 0.0,
                1.0),
       }},
  };
  return s;
}

}  // namespace

const Schema& LubricantSchema() {
  static const Schema schema = BuildLubricantSchema();
  return schema;
}

}  // namespace tehl::internal
